// Which parameter tables fill a Scene, in which order: the one list that the scene reader
// (scene.cpp) and the generated columns of docs/scene-format.md (scene_format_doc.cpp) walk.
// A new key is a row in its struct's table; a new params struct is one line here.
#pragma once

#include <span>
#include <string_view>
#include <type_traits>

#include "cli/scene.h"
#include "povgen/export_params.h"
#include "sim/camera.h"
#include "sim/param_table.h"
#include "sim/params.h"

namespace raintrace::cli {

/// The sections of a scene file in the order they are read and documented; "" is the top
/// level (`seed`).
inline constexpr std::string_view kSections[] = {
    "",        "output",    "camera", "rain",        "wind",   "splashes",  "puddles",
    "ripples", "lightning", "fog",    "environment", "export", "simulation"};

/// Calls visit(table, object) for every params struct that a scene file fills: `table` a
/// std::span of its rows, `object` the part of `scene` it fills. Within a section the rows of
/// earlier tables come first: [output] starts with Scene's frames, [lightning] ends with
/// ExportParams' light.
template <class SceneType, class Visit>
void for_each_table(SceneType& scene, Visit&& visit) {
  static_assert(std::is_same_v<std::remove_const_t<SceneType>, Scene>);
  visit(std::span<const sim::Param<sim::SimParams>>(sim::kSimParams), scene.sim);
  visit(std::span<const sim::Param<Scene>>(kSceneParams), scene);
  visit(std::span<const sim::Param<sim::Camera>>(sim::kCameraParams), scene.sim.camera);
  visit(std::span<const sim::Param<film::DevelopSettings>>(kDevelopParams), scene.develop);
  visit(std::span<const sim::Param<sim::RainParams>>(sim::kRainParams), scene.sim.rain);
  visit(std::span<const sim::Param<sim::WindParams>>(sim::kWindParams), scene.sim.wind);
  visit(std::span<const sim::Param<sim::SplashParams>>(sim::kSplashParams), scene.sim.splashes);
  visit(std::span<const sim::Param<sim::PuddleParams>>(sim::kPuddleParams), scene.sim.puddles);
  visit(std::span<const sim::Param<sim::RippleParams>>(sim::kRippleParams), scene.sim.ripples);
  visit(std::span<const sim::Param<sim::LightningParams>>(sim::kLightningParams),
        scene.sim.lightning);
  visit(std::span<const sim::Param<povgen::ExportParams>>(povgen::kExportParams), scene.look);
  visit(std::span<const sim::Param<povgen::FogParams>>(povgen::kFogParams), scene.look.fog);
  visit(std::span<const sim::Param<povgen::EnvironmentParams>>(povgen::kEnvironmentParams),
        scene.look.environment);
}

}  // namespace raintrace::cli
