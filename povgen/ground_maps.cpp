// Screen-space puddle mask and ripple map (see ground_maps.h).
#include "povgen/ground_maps.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

#include "sim/ground_impacts.h"

namespace raintrace::povgen {
namespace {

constexpr double kPi = std::numbers::pi;

std::uint16_t to_u16(double v) {
  // Rounds to nearest: the value is not negative (std::lround costs a call a channel here).
  return static_cast<std::uint16_t>(std::clamp(v, 0.0, 1.0) * 65535.0 + 0.5);
}

}  // namespace

GroundPixels::GroundPixels(const sim::Camera& camera, int width, int height, double ground_y)
    : m_camera(camera), m_ground_y(ground_y), m_width(width), m_height(height) {
  m_eye = camera.position;
  m_forward = glm::normalize(camera.look_at - camera.position);
  // POV-Ray's look_at keeps `sky` (+y) up; straight up or down falls back to +z (view_frustum).
  glm::dvec3 sky{0.0, 1.0, 0.0};
  if (std::abs(glm::dot(sky, m_forward)) > 0.9999) sky = {0.0, 0.0, 1.0};
  m_right = glm::normalize(glm::cross(sky, m_forward));
  m_up = glm::cross(m_forward, m_right);
  m_tan_x = std::tan(camera.fov_deg * kPi / 360.0);
  m_tan_y = m_tan_x * height / width;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  m_x.assign(n, 0.0f);
  m_z.assign(n, 0.0f);
  m_across.assign(n, 0.0f);
  m_along.assign(n, 0.0f);
  m_dir.assign(2 * n, 0.0f);
  if (!(m_eye.y > ground_y)) return;
  const double reach2 = sim::ImpactSampler::kMaxDistance_m * sim::ImpactSampler::kMaxDistance_m;
  auto ray = [&](double column, double row) {
    const double sx = (2.0 * column / width - 1.0) * m_tan_x;
    const double sy = (1.0 - 2.0 * row / height) * m_tan_y;
    return m_forward + sx * m_right + sy * m_up;
  };
  auto hit = [&](const glm::dvec3& d, glm::dvec3& p) {
    if (!(d.y < 0.0)) return false;
    p = m_eye + d * ((ground_y - m_eye.y) / d.y);
    return true;
  };
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const glm::dvec3 d = ray(i + 0.5, j + 0.5);
      glm::dvec3 p, above, below;
      if (!hit(d, p)) continue;
      const double dx = p.x - m_eye.x, dz = p.z - m_eye.z;
      if (dx * dx + dz * dz > reach2) continue;
      const std::size_t k = static_cast<std::size_t>(j) * width + i;
      m_x[k] = static_cast<float>(p.x);
      m_z[k] = static_cast<float>(p.z);
      // Across: neighbouring columns' rays are 2·tan_x/width apart per unit of ray parameter.
      const double t = (ground_y - m_eye.y) / d.y;
      const double across = t * 2.0 * m_tan_x / width;
      // Along: where the rays half a row up and down meet the ground (far away, only the
      // nearer one may).
      double along = across;
      if (hit(ray(i + 0.5, j + 1.0), below)) {
        along =
            hit(ray(i + 0.5, j), above) ? glm::length(above - below) : 2.0 * glm::length(p - below);
      }
      const glm::dvec3 h = glm::normalize(glm::dvec3{d.x, 0.0, d.z});
      m_across[k] = static_cast<float>(across);
      m_along[k] = static_cast<float>(std::max(along, across));
      m_dir[2 * k] = static_cast<float>(h.x);
      m_dir[2 * k + 1] = static_cast<float>(h.z);
    }
  }
}

sim::PixelSpan GroundPixels::span(std::size_t p) const {
  return {m_across[p], m_along[p], m_dir[2 * p], m_dir[2 * p + 1]};
}

bool GroundPixels::project(double x, double z, double& column, double& row) const {
  const glm::dvec3 q = glm::dvec3{x, m_ground_y, z} - m_eye;
  const double depth = glm::dot(q, m_forward);
  if (!(depth > 1e-6)) return false;
  column = (glm::dot(q, m_right) / (depth * m_tan_x) + 1.0) * 0.5 * m_width;
  row = (1.0 - glm::dot(q, m_up) / (depth * m_tan_y)) * 0.5 * m_height;
  return true;
}

bool GroundPixels::matches(const sim::Camera& camera, int width, int height,
                           double ground_y) const {
  return width == m_width && height == m_height && ground_y == m_ground_y &&
         camera.position == m_camera.position && camera.look_at == m_camera.look_at &&
         camera.fov_deg == m_camera.fov_deg;
}

std::vector<float> puddle_mask(const GroundPixels& pixels, const sim::PuddleField& puddles) {
  std::vector<float> mask(static_cast<std::size_t>(pixels.width()) * pixels.height(), 0.0f);
  if (puddles.empty()) return mask;
  for (std::size_t p = 0; p < mask.size(); ++p) {
    if (pixels.hits(p)) mask[p] = static_cast<float>(puddles.share(pixels.x(p), pixels.z(p)));
  }
  return mask;
}

namespace {

/// The film stirred by one impact (sim::film_stir over sim::stirred_radius): every pixel whose
/// ground lies in the patch, or, for a patch smaller than its pixel, that pixel by the share of
/// it the patch covers. False if the patch is out of view.
bool stir_film(const GroundPixels& pixels, const sim::Ripple& ripple, RippleMap& map) {
  const double stir = sim::film_stir(ripple);
  const double radius = sim::stirred_radius(ripple);
  double column = 0.0, row = 0.0;
  if (stir <= 0.0 || !pixels.project(ripple.x, ripple.z, column, row)) return false;
  const int w = pixels.width(), h = pixels.height();
  if (column < 0.0 || row < 0.0 || column >= w || row >= h) return false;
  const std::size_t centre = static_cast<std::size_t>(row) * static_cast<std::size_t>(w) +
                             static_cast<std::size_t>(column);
  if (!pixels.hits(centre)) return false;
  auto add = [&](std::size_t p, double amount) {
    map.film[p] = std::min(1.0f, map.film[p] + static_cast<float>(amount));
  };
  const sim::PixelSpan span = pixels.span(centre);
  const double patch = kPi * radius * radius;
  const double pixel = span.across_m * span.along_m;
  if (patch < pixel) {
    add(centre, stir * patch / pixel);
    return true;
  }
  // Larger than a pixel: the pixels around whose ground is within the radius.
  const int reach = static_cast<int>(std::ceil(radius / span.across_m)) + 1;
  const int i0 = std::max(0, static_cast<int>(column) - reach);
  const int i1 = std::min(w - 1, static_cast<int>(column) + reach);
  const int j0 = std::max(0, static_cast<int>(row) - reach);
  const int j1 = std::min(h - 1, static_cast<int>(row) + reach);
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * w + i;
      const double dx = pixels.x(p) - ripple.x, dz = pixels.z(p) - ripple.z;
      if (pixels.hits(p) && dx * dx + dz * dz <= radius * radius) {
        add(p, stir);
      }
    }
  }
  return true;
}

}  // namespace

void draw_ripples(const GroundPixels& pixels, const std::vector<sim::Ripple>& ripples,
                  RippleMap& map) {
  const int w = pixels.width(), h = pixels.height();
  const std::size_t n = static_cast<std::size_t>(w) * h;
  map.width = w;
  map.height = h;
  map.height_m.assign(n, 0.0f);
  map.film.assign(n, 0.0f);
  for (const sim::Ripple& ripple : ripples) {
    if (!ripple.on_puddle) {
      stir_film(pixels, ripple, map);
      continue;
    }
    const double reach = sim::ripple_reach(ripple);
    // The ring's square on the ground, projected: its screen box.
    double c0 = 1e300, c1 = -1e300, r0 = 1e300, r1 = -1e300;
    bool in_front = true;
    for (const double dx : {-reach, reach}) {
      for (const double dz : {-reach, reach}) {
        double c = 0.0, r = 0.0;
        in_front = in_front && pixels.project(ripple.x + dx, ripple.z + dz, c, r);
        c0 = std::min(c0, c);
        c1 = std::max(c1, c);
        r0 = std::min(r0, r);
        r1 = std::max(r1, r);
      }
    }
    if (!in_front || c1 < 0.0 || r1 < 0.0 || c0 >= w || r0 >= h) continue;
    const sim::RippleRing ring(ripple);
    const int i0 = std::max(0, static_cast<int>(std::floor(c0)));
    const int i1 = std::min(w - 1, static_cast<int>(std::ceil(c1)));
    const int j0 = std::max(0, static_cast<int>(std::floor(r0)));
    const int j1 = std::min(h - 1, static_cast<int>(std::ceil(r1)));
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const std::size_t p = static_cast<std::size_t>(j) * w + i;
        if (!pixels.hits(p)) continue;
        map.height_m[p] +=
            static_cast<float>(ring.height_at(pixels.x(p), pixels.z(p), pixels.span(p)));
      }
    }
  }
}

std::vector<std::uint16_t> ripple_pixels(const RippleMap& map) {
  std::vector<std::uint16_t> out(2 * map.height_m.size());
  for (std::size_t p = 0; p < map.height_m.size(); ++p) {
    out[2 * p] = to_u16(0.5 + map.height_m[p] / kRippleHeightRange);
    // Calm: opaque (ground_maps.h); POV-Ray reads the stir back as transmit.
    out[2 * p + 1] = to_u16(1.0 - map.film[p]);
  }
  return out;
}

namespace {

void write_png(const std::filesystem::path& path, int width, int height, int channels,
               OIIO::TypeDesc type, const void* pixels) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw std::runtime_error("cannot write " + path.string() + ": " + OIIO::geterror());
  OIIO::ImageSpec spec(width, height, channels, type);
  // The channels are data, not colour with a premultiplied alpha: written as they are.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  // zlib's fastest level and no row filter: a frame's map is written once and read once, and
  // libpng's default (level 6, each row's best of five filters) was a fifth of a frame's whole
  // export. Measured on heavy_rain's map: 95 KB as before, 98 KB like this.
  spec.attribute("png:compressionLevel", 1);
  spec.attribute("png:filter", 8);  // PNG_FILTER_NONE
  if (!out->open(path.string(), spec) || !out->write_image(type, pixels) || !out->close()) {
    throw std::runtime_error("cannot write " + path.string() + ": " + out->geterror());
  }
}

}  // namespace

void write_mask_png(const std::filesystem::path& path, int width, int height,
                    const std::vector<float>& values) {
  std::vector<std::uint8_t> bytes(values.size());
  for (std::size_t p = 0; p < values.size(); ++p) {
    bytes[p] = static_cast<std::uint8_t>(std::lround(std::clamp(values[p], 0.0f, 1.0f) * 255.0f));
  }
  write_png(path, width, height, 1, OIIO::TypeDesc::UINT8, bytes.data());
}

void write_ripple_png(const std::filesystem::path& path, const RippleMap& map) {
  const std::vector<std::uint16_t> pixels = ripple_pixels(map);
  write_png(path, map.width, map.height, 2, OIIO::TypeDesc::UINT16, pixels.data());
}

}  // namespace raintrace::povgen
