// The hot loop (see integrator.h). Drops go through in blocks: first a branch-free arithmetic
// pass over plain float arrays (so the compiler can vectorise it) that also writes an
// "event" byte per drop, then a scan of those bytes that collects the rare events. Turbulence
// (a per-drop wind) is evaluated into a block buffer, one mode at a time with sin_approx, so
// that it vectorises too.
#include "sim/integrator.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/terminal_velocity.h"

namespace raintrace::sim {
namespace {

constexpr std::size_t kBlock = 256;

enum : std::uint8_t { kStay = 0, kGround = 1, kGone = 2 };

// Block-local structure of arrays: the Frame's vec3 arrays are interleaved (x, y, z), which
// compilers do not vectorise well, so each block is transposed in, computed, transposed out.
struct Block {
  std::array<float, kBlock> px, py, pz, vx, vy, vz, ax, ay, az, wx, wy, wz, sin;
  std::array<std::uint8_t, kBlock> event;
};

// Per-drop wind of the block (turbulence at the drop, then the uniform part) into b.wx/wy/wz.
void turbulence_block(const Wind& wind, const StepConstants& c, std::size_t n, Block& b) {
  turbulence_of(wind.modes(), c.time_s, n, b.px.data(), b.py.data(), b.pz.data(), b.wx.data(),
                b.wy.data(), b.wz.data(), b.sin.data());
  const float cwx = c.wind.x, cwy = c.wind.y, cwz = c.wind.z;
  for (std::size_t i = 0; i < n; ++i) b.wx[i] += cwx, b.wy[i] += cwy, b.wz[i] += cwz;
}

// One block of drops [begin, begin + n). b.wx/wy/wz hold the per-drop wind when kTurbulent,
// else the uniform wind c.wind applies.
template <bool kTurbulent, bool kFading>
void integrate_block(DropState& state, std::size_t begin, std::size_t n, const StepConstants& c,
                     Block& b) {
  glm::vec3* pos = state.drops.position.data() + begin;
  glm::vec3* vel = state.drops.velocity.data() + begin;
  glm::vec3* acc = state.drops.acceleration.data() + begin;
  for (std::size_t i = 0; i < n; ++i) {
    b.px[i] = pos[i].x, b.py[i] = pos[i].y, b.pz[i] = pos[i].z;
    b.vx[i] = vel[i].x, b.vy[i] = vel[i].y, b.vz[i] = vel[i].z;
  }
  if constexpr (kTurbulent) turbulence_block(*c.turbulence, c, n, b);
  float* __restrict age = state.drops.age.data() + begin;
  float* __restrict opacity = state.drops.opacity.data() + begin;
  const float* __restrict rate = state.drops.vanishing_rate.data() + begin;
  const float* __restrict drag = state.drag.data() + begin;
  const float dt = c.dt, inv_dt = 1.0f / c.dt;
  const auto g = static_cast<float>(kGravity);
  const float ox = c.origin.x, oz = c.origin.z;
  const float ax = c.across.x, az = c.across.z, bx = c.along.x, bz = c.along.z;
  // Locals, not c's fields: the stores below could alias c as far as the compiler knows,
  // which would force reloads and block vectorisation.
  const float cwx = c.wind.x, cwy = c.wind.y, cwz = c.wind.z;
  const float a0 = c.a0, a1 = c.a1, b0 = c.b0, b1 = c.b1;
  const float ceiling = c.ceiling, ground = c.ground, min_opacity = c.min_opacity;
  const float fa0 = c.fa0, fa1 = c.fa1, fb0 = c.fb0, fb1 = c.fb1;
  const float ea0 = c.ea0, ea1 = c.ea1, eb0 = c.eb0, eb1 = c.eb1;
  const float inv_g = 1.0f / g;
  float* __restrict px = b.px.data();
  float* __restrict py = b.py.data();
  float* __restrict pz = b.pz.data();
  float* __restrict vx = b.vx.data();
  float* __restrict vy = b.vy.data();
  float* __restrict vz = b.vz.data();
  float* __restrict acx = b.ax.data();
  float* __restrict acy = b.ay.data();
  float* __restrict acz = b.az.data();
  const float* __restrict bwx = b.wx.data();
  const float* __restrict bwy = b.wy.data();
  const float* __restrict bwz = b.wz.data();
  std::uint8_t* __restrict event = b.event.data();
  for (std::size_t i = 0; i < n; ++i) {
    const float wx = kTurbulent ? bwx[i] : cwx;
    const float wy = kTurbulent ? bwy[i] : cwy;
    const float wz = kTurbulent ? bwz[i] : cwz;
    const float ux = wx - vx[i], uy = wy - vy[i], uz = wz - vz[i];
    const float ku = drag[i] * std::sqrt(ux * ux + uy * uy + uz * uz);
    const float inv = 1.0f / (1.0f + ku * dt);
    const float nx = (vx[i] + dt * ku * wx) * inv;
    const float ny = (vy[i] + dt * (ku * wy - g)) * inv;
    const float nz = (vz[i] + dt * ku * wz) * inv;
    acx[i] = (nx - vx[i]) * inv_dt;
    acy[i] = (ny - vy[i]) * inv_dt;
    acz[i] = (nz - vz[i]) * inv_dt;
    vx[i] = nx, vy[i] = ny, vz[i] = nz;
    const float qx = px[i] + dt * nx, qy = py[i] + dt * ny, qz = pz[i] + dt * nz;
    px[i] = qx, py[i] = qy, pz[i] = qz;
    age[i] += dt;
    float o = opacity[i];
    if constexpr (kFading) {
      o = o / (1.0f + rate[i] * dt);
      opacity[i] = o;
    }
    const float rx = qx - ox, rz = qz - oz;
    const float a = rx * ax + rz * az;
    const float bb = rx * bx + rz * bz;
    // How far beyond the footprint this drop can be and still drift onto it: height above the
    // ground / terminal speed (drag = g / v_t², so 1/v_t = sqrt(drag / g)) × drift speed.
    const float reach = (qy - ground) * std::sqrt(drag[i] * inv_g);
    // Written so that NaN anywhere makes `inside` false and the drop leaves.
    const int inside =
        static_cast<int>(a >= a0) & static_cast<int>(a <= a1) & static_cast<int>(bb >= b0) &
        static_cast<int>(bb <= b1) & static_cast<int>(a >= fa0 - reach * ea0) &
        static_cast<int>(a <= fa1 + reach * ea1) & static_cast<int>(bb >= fb0 - reach * eb0) &
        static_cast<int>(bb <= fb1 + reach * eb1) & static_cast<int>(qy <= ceiling) &
        static_cast<int>(o >= min_opacity);
    const int below = static_cast<int>(!(qy > ground));
    // kGone if outside, else kGround if below, else kStay — without a branch.
    event[i] = static_cast<std::uint8_t>(kGone - inside * (kGone - below * kGround));
  }
  for (std::size_t i = 0; i < n; ++i) {
    pos[i] = {b.px[i], b.py[i], b.pz[i]};
    vel[i] = {b.vx[i], b.vy[i], b.vz[i]};
    acc[i] = {b.ax[i], b.ay[i], b.az[i]};
  }
}

template <bool kTurbulent, bool kFading>
void integrate_all(DropState& state, std::size_t begin, std::size_t end, const StepConstants& c,
                   StepEvents& events) {
  Block block;
  for (std::size_t b = begin; b < end; b += kBlock) {
    const std::size_t n = std::min(kBlock, end - b);
    integrate_block<kTurbulent, kFading>(state, b, n, c, block);
    for (std::size_t i = 0; i < n; ++i) {
      if (block.event[i] == kStay) [[likely]]
        continue;
      (block.event[i] == kGround ? events.ground : events.gone)
          .push_back(static_cast<std::uint32_t>(b + i));
    }
  }
}

}  // namespace

void integrate_range(DropState& state, std::size_t begin, std::size_t end, const StepConstants& c,
                     StepEvents& events) {
  const bool turbulent = c.turbulence != nullptr;
  if (turbulent && c.fading) return integrate_all<true, true>(state, begin, end, c, events);
  if (turbulent) return integrate_all<true, false>(state, begin, end, c, events);
  if (c.fading) return integrate_all<false, true>(state, begin, end, c, events);
  integrate_all<false, false>(state, begin, end, c, events);
}

}  // namespace raintrace::sim
