#include "scene/boat_hull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "scene/mesh_builders.h"

namespace ocean_scene {
namespace {

constexpr int kStations = 28;  // cross-sections from the transom to the stem

// A cross-section's rows from the keel up: height as a share of the draft (below the waterline,
// negative) or of the freeboard (above it), and the half-width as a share of the station's
// half-beam. Row kWaterline lies exactly on the waterline, where the hull is split.
struct Row {
  double height, width;
};
constexpr std::array<Row, 9> kRows = {{{-1.0, 0.0},
                                       {-0.8, 0.55},
                                       {-0.55, 0.8},
                                       {-0.3, 0.93},
                                       {0.0, 0.943},
                                       {0.35, 0.965},
                                       {0.7, 0.985},
                                       {0.85, 0.993},
                                       {1.0, 1.0}}};
constexpr std::size_t kWaterline = 4, kStrake = 7;

double shareAlong(const BoatHullShape& shape, double x) {
  return std::clamp(x / shape.length, 0.0, 1.0);
}

// The draft shoals toward the stem (the forefoot rises) and the sheer rises toward it.
double draftAt(const BoatHullShape& shape, double u) {
  return shape.draft * (1.0 - 0.55 * std::pow(u, 4.0));
}

double rowHeight(const BoatHullShape& shape, double u, const Row& row) {
  return row.height < 0.0 ? row.height * draftAt(shape, u)
                          : row.height * boatDeckHeight(shape, u * shape.length);
}

// Position of row k at station i on the starboard (side +1) or port (side -1) side.
glm::vec3 hullPoint(const BoatHullShape& shape, int i, std::size_t k, double side) {
  const double u = double(i) / double(kStations);
  const double x = u * shape.length;
  return glm::vec3(float(x), float(rowHeight(shape, u, kRows[k])),
                   float(side * kRows[k].width * boatHalfBeam(shape, x)));
}

// The sides between rows [k0, k1]: a strip per side, smooth normals, starboard counter-clockwise
// seen from +z and port from -z.
Mesh sideStrips(const BoatHullShape& shape, std::size_t k0, std::size_t k1, const char* name) {
  Mesh mesh;
  mesh.name = name;
  const auto rows = std::uint32_t(k1 - k0 + 1);
  for (double side : {1.0, -1.0}) {
    const auto base = std::uint32_t(mesh.positions.size());
    for (int i = 0; i <= kStations; ++i)
      for (std::size_t k = k0; k <= k1; ++k) mesh.positions.push_back(hullPoint(shape, i, k, side));
    for (std::uint32_t i = 0; i < std::uint32_t(kStations); ++i) {
      for (std::uint32_t k = 0; k + 1 < rows; ++k) {
        const std::uint32_t a = base + i * rows + k, b = a + rows, c = b + 1, d = a + 1;
        // Along x then up is +z: counter-clockwise from outside on the starboard side.
        if (side > 0.0) {
          mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
        } else {
          mesh.indices.insert(mesh.indices.end(), {a, c, b, a, d, c});
        }
      }
    }
  }
  computeSmoothNormals(mesh);
  return mesh;
}

// The transom between rows [k0, k1]: a flat fan facing -x, appended to `mesh`.
void addTransom(Mesh& mesh, const BoatHullShape& shape, std::size_t k0, std::size_t k1) {
  std::vector<glm::vec3> outline;  // up the starboard side, down the port side
  for (std::size_t k = k0; k <= k1; ++k) outline.push_back(hullPoint(shape, 0, k, 1.0));
  for (std::size_t k = k1 + 1; k-- > k0;) {
    if (kRows[k].width > 0.0) outline.push_back(hullPoint(shape, 0, k, -1.0));
  }
  glm::vec3 centre(0.0f);
  for (const glm::vec3& p : outline) centre += p;
  centre /= float(outline.size());
  const auto base = std::uint32_t(mesh.positions.size());
  mesh.positions.push_back(centre);
  mesh.normals.emplace_back(-1.0f, 0.0f, 0.0f);
  for (const glm::vec3& p : outline) {
    mesh.positions.push_back(p);
    mesh.normals.emplace_back(-1.0f, 0.0f, 0.0f);
  }
  const auto n = std::uint32_t(outline.size());
  for (std::uint32_t j = 0; j < n; ++j) {
    const std::uint32_t a = base + 1 + j, b = base + 1 + (j + 1) % n;
    // Up the starboard side (+z) and down the port side is counter-clockwise seen from -x.
    if (glm::length(glm::cross(mesh.positions[a] - centre, mesh.positions[b] - centre)) > 0.0f)
      mesh.indices.insert(mesh.indices.end(), {base, a, b});
  }
}

}  // namespace

double boatDeckHeight(const BoatHullShape& shape, double x) {
  const double u = shareAlong(shape, x);
  return shape.freeboard * (1.0 + 0.3 * u * u);
}

double boatHalfBeam(const BoatHullShape& shape, double x) {
  const double u = shareAlong(shape, x);
  const double half = 0.5 * shape.beam;
  // Full beam from 30 % to 40 % of the length; the transom 88 % of it; an elliptic bow.
  if (u < 0.3) return half * (0.88 + 0.12 * std::sin(0.5 * 3.14159265358979 * u / 0.3));
  if (u < 0.4) return half;
  const double t = (u - 0.4) / 0.6;
  return half * std::sqrt(std::max(0.0, 1.0 - t * t));
}

BoatHull buildBoatHull(const BoatHullShape& shape) {
  BoatHull hull;
  hull.bottom = sideStrips(shape, 0, kWaterline, "boat_bottom");
  addTransom(hull.bottom, shape, 0, kWaterline);
  hull.topsides = sideStrips(shape, kWaterline, kStrake, "boat_topsides");
  addTransom(hull.topsides, shape, kWaterline, kRows.size() - 1);
  hull.strake = sideStrips(shape, kStrake, kRows.size() - 1, "boat_strake");

  // The deck: the gunwales joined across, station by station, facing up.
  Mesh& deck = hull.deck;
  deck.name = "boat_deck";
  const std::size_t top = kRows.size() - 1;
  for (int i = 0; i <= kStations; ++i) {
    deck.positions.push_back(hullPoint(shape, i, top, -1.0));
    deck.positions.push_back(hullPoint(shape, i, top, 1.0));
  }
  for (std::uint32_t i = 0; i < std::uint32_t(kStations); ++i) {
    const std::uint32_t port = 2 * i, starboard = port + 1, nextPort = port + 2,
                        nextStarboard = port + 3;
    // Across (+z) then along (+x) is -y: (port, nextPort, nextStarboard) turns the other way.
    deck.indices.insert(deck.indices.end(),
                        {port, nextStarboard, nextPort, port, starboard, nextStarboard});
  }
  computeSmoothNormals(deck);
  return hull;
}

}  // namespace ocean_scene
