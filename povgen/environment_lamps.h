// Where a built-in environment's lamps are, for the rain drawn around them beyond far_m
// (sim/lamp_rain.h). The simulation cannot read the templates, so their layout is repeated here
// (environment_lamps_test.cpp checks it against the template's text). Header-only, like the
// parameter tables: the scene loader links no povgen code.
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <string_view>
#include <vector>

namespace raintrace::povgen {

/// The lenses of the environment's street lights (m): night_street's seven; none for the other
/// environments.
inline std::vector<glm::dvec3> environment_lamps(std::string_view environment_name) {
  // templates/night_street/streetlights.inc: RT_StreetLight(Z, Side, …) puts the lens at
  // <Side·(RT_KerbX − 1.4), RT_LampHeight − 0.07, Z>, with RT_KerbX = 4 and RT_LampHeight = 6.
  struct StreetLight {
    double z;
    int side;
  };
  constexpr std::array<StreetLight, 7> kNightStreetLights{
      {{5, 1}, {16, -1}, {28, 1}, {40, -1}, {52, 1}, {88, -1}, {112, 1}}};
  constexpr double kLensX = 4.0 - 1.4;
  constexpr double kLensY = 6.0 - 0.07;
  std::vector<glm::dvec3> lenses;
  if (environment_name != "night_street") return lenses;
  for (const StreetLight& light : kNightStreetLights) {
    lenses.emplace_back(light.side * kLensX, kLensY, light.z);
  }
  return lenses;
}

}  // namespace raintrace::povgen
