// The lens barrel's rim: its place from the opening and the field (lens_barrel.h), and its text.
#include "povgen/lens_barrel.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

#include "povgen/number_format.h"

namespace raintrace::povgen {

double half_diagonal_tan(const ExportParams& look) {
  const double half_width = std::tan(look.camera.fov_deg * M_PI / 360.0);
  const double height_over_width = static_cast<double>(look.height) / look.width;
  return half_width * std::sqrt(1.0 + height_over_width * height_over_width);
}

LensBarrel lens_barrel(const ExportParams& look) {
  if (!(look.optical_vignetting > 0.0)) {
    throw std::invalid_argument("lens_barrel: optical_vignetting is 0, so there is no rim");
  }
  check_optical_vignetting(look);
  // POV-Ray's `aperture` is twice aperture_m (scene_files.cpp): the opening's radius is half
  // of aperture_m.
  const double opening_radius = look.aperture_m / 2.0;
  const double focus = glm::length(look.camera.look_at - look.camera.position);
  const double corner = half_diagonal_tan(look);
  LensBarrel barrel;
  barrel.distance_m = opening_radius / (look.optical_vignetting * corner + opening_radius / focus);
  barrel.hole_radius_m = barrel.distance_m * corner;
  return barrel;
}

std::string lens_barrel_text(const ExportParams& look) {
  if (look.optical_vignetting == 0.0) return {};
  const LensBarrel barrel = lens_barrel(look);
  const glm::dvec3 view = glm::normalize(look.camera.look_at - look.camera.position);
  const glm::dvec3 centre = look.camera.position + view * barrel.distance_m;
  // Wide enough to stop every ray that misses the hole: a pixel's rays lie within the opening's
  // radius of its chief ray, which at the corner crosses the rim's plane on the hole's edge.
  const double outer = 2.0 * (barrel.hole_radius_m + look.aperture_m);
  // Black and seen by the camera's rays only: it casts no shadow, no mirror shows it, and the
  // photons of a caustic pass it by.
  return "// The lens barrel's rim ([camera] optical_vignetting): cat's-eye discs at the "
         "corners.\n"
         "disc{" +
         format_vector(centre) + "," + format_vector(view) + "," + format_number(outer) + "," +
         format_number(barrel.hole_radius_m) +
         " pigment{rgb 0} finish{ambient 0 diffuse 0 emission 0}"
         " no_shadow no_reflection photons{collect off pass_through}}\n";
}

}  // namespace raintrace::povgen
