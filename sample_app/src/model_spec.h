#pragma once
// The --model argument: FILE[@x,y,z][:fit=metres|:fit=none]. Users' glTF files come in any
// unit and origin (a 79 m fox, a 10 cm amber piece), so by default a model is scaled to a
// size that reads well in the seabed view and set down on the sand.

#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace ocean {

// The size the largest side of a model's bounding box is scaled to when no :fit= is given.
inline constexpr double kDefaultFitMetres = 1.5;

struct ModelSpec {
  std::string path;
  // x, z: where the box's centre goes; y: height of the box's bottom above the sand
  // (0 = resting on it). Unset: the sample's row of user models, resting on the sand.
  std::optional<glm::dvec3> position;
  // Largest bounding-box side in metres; nullopt (:fit=none) keeps the file's own size.
  std::optional<double> fitMetres = kDefaultFitMetres;
};

// Parses from the end, so a path may contain ':' (a '@' in a path needs a position suffix).
// Returns false with a one-line reason.
bool parseModelSpec(const std::string& text, ModelSpec& out, std::string& error);

// The transform that fits the model-space box [lo, hi] as `spec` asks and puts it at (x, z)
// with its bottom `y` above `sandHeight` (the seabed height at x, z). `defaultXZ` is used when
// the spec has no position. False when the box is empty or not finite.
bool placementTransform(const ModelSpec& spec, const glm::dvec3& lo, const glm::dvec3& hi,
                        const glm::dvec2& defaultXZ, double (*sandHeight)(double x, double z),
                        glm::dmat4& out, std::string& error);

}  // namespace ocean
