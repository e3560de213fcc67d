// The World's drops: the snapshot's structure of arrays plus what only the integrator needs
// (the drag coefficient, precomputed per drop so the hot loop never evaluates exp()).
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "sim/frame.h"

namespace raintrace::sim {

struct NewDrop {
  std::uint64_t id = 0;
  glm::vec3 position{0.0f};
  glm::vec3 velocity{0.0f};
  float diameter = 0.0f;  ///< m
  float age = 0.0f;       ///< s
  float vanishing_rate = 0.0f;
  float opacity = 1.0f;
  glm::vec3 colour{1.0f};
};

struct DropState {
  Drops drops;
  std::vector<float> drag;  ///< k = g / v_t², 1/m (see terminal_velocity.h)

  [[nodiscard]] std::size_t size() const { return drops.size(); }
  void reserve(std::size_t n);
  void push(const NewDrop& d);
  /// Removes drop i by moving the last drop into its place (order changes deterministically).
  void swap_remove(std::size_t i);
  /// Recomputes drag after the diameter of drop i changed.
  void refresh_drag(std::size_t i);
};

}  // namespace raintrace::sim
