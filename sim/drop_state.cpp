// Push/remove on the drop arrays (see drop_state.h).
#include "sim/drop_state.h"

#include "sim/terminal_velocity.h"

namespace raintrace::sim {
namespace {
template <typename T>
void move_last_into(std::vector<T>& v, std::size_t i) {
  v[i] = v.back();
  v.pop_back();
}
}  // namespace

void DropState::reserve(std::size_t n) {
  drops.id.reserve(n);
  drops.position.reserve(n);
  drops.velocity.reserve(n);
  drops.acceleration.reserve(n);
  drops.diameter.reserve(n);
  drops.age.reserve(n);
  drops.vanishing_rate.reserve(n);
  drops.opacity.reserve(n);
  drops.colour.reserve(n);
  drag.reserve(n);
}

void DropState::push(const NewDrop& d) {
  drops.id.push_back(d.id);
  drops.position.push_back(d.position);
  drops.velocity.push_back(d.velocity);
  drops.acceleration.push_back(glm::vec3{0.0f});
  drops.diameter.push_back(d.diameter);
  drops.age.push_back(d.age);
  drops.vanishing_rate.push_back(d.vanishing_rate);
  drops.opacity.push_back(d.opacity);
  drops.colour.push_back(d.colour);
  drag.push_back(static_cast<float>(drag_coefficient(d.diameter)));
}

void DropState::swap_remove(std::size_t i) {
  move_last_into(drops.id, i);
  move_last_into(drops.position, i);
  move_last_into(drops.velocity, i);
  move_last_into(drops.acceleration, i);
  move_last_into(drops.diameter, i);
  move_last_into(drops.age, i);
  move_last_into(drops.vanishing_rate, i);
  move_last_into(drops.opacity, i);
  move_last_into(drops.colour, i);
  move_last_into(drag, i);
}

void DropState::refresh_drag(std::size_t i) {
  drag[i] = static_cast<float>(drag_coefficient(drops.diameter[i]));
}

}  // namespace raintrace::sim
