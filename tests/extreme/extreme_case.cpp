#include "extreme_case.h"

#include <algorithm>

namespace extreme {

const char* passName(Pass pass) {
  switch (pass) {
    case Pass::Caustics:
      return "caustics";
    case Pass::CausticsDispersion:
      return "caustics_dispersion";
    case Pass::CausticsShadow:
      return "caustics_shadow";
    case Pass::GodRaysFull:
      return "godrays_full";
    case Pass::GodRaysHalf:
      return "godrays_half";
    case Pass::Water:
      return "water";
    case Pass::Count:
      break;
  }
  return "unknown";
}

bool isCausticPass(Pass pass) {
  return (passBit(pass) & kCaustics) != 0;
}
bool isGodRayPass(Pass pass) {
  return (passBit(pass) & kGodRays) != 0;
}

const char* sweepName(Sweep sweep) {
  switch (sweep) {
    case Sweep::None:
      return "none";
    case Sweep::SunElevation:
      return "sun elevation (rad)";
    case Sweep::Tau:
      return "tau (relative)";
    case Sweep::Absorption:
      return "absorption (1/m)";
    case Sweep::WaterLevel:
      return "water level (m)";
    case Sweep::Ior:
      return "IOR";
    case Sweep::Time:
      return "time (s)";
  }
  return "unknown";
}

Knobs Case::knobs() const {
  Knobs k;
  row->edit(k);
  return k;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const Row& row : rows()) {
    for (int p = 0; p < static_cast<int>(Pass::Count); ++p) {
      const Pass pass = static_cast<Pass>(p);
      if ((row.passes & passBit(pass)) == 0) continue;
      out.push_back({&row, pass, std::string(row.name) + "_" + passName(pass)});
    }
  }
  return out;
}

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

Knobs stepped(const Knobs& knobs, Sweep sweep) {
  Knobs k = knobs;
  switch (sweep) {
    case Sweep::None:
      break;
    case Sweep::SunElevation:
      k.sunElevationDeg += kStep * 57.29577951308232;
      break;
    case Sweep::Tau: {
      // At the top of the range (1e6) the step goes down instead.
      const double step = kStep * std::max(static_cast<double>(k.tau), 1.0);
      k.tau = static_cast<float>(double(k.tau) + (double(k.tau) + step > 1e6 ? -step : step));
      break;
    }
    case Sweep::Absorption:
      k.absorption = static_cast<float>(double(k.absorption) +
                                        kStep * std::max(static_cast<double>(k.absorption), 1.0));
      break;
    case Sweep::WaterLevel:  // the level rises; camera and scene stay put
      k.cameraBelowLevel += kStep;
      k.floorBelowLevel += kStep;
      break;
    case Sweep::Ior:
      k.ior = static_cast<float>(double(k.ior) + kStep);
      break;
    case Sweep::Time:
      k.oceanTime += kStep;
      break;
  }
  return k;
}

}  // namespace extreme
