// Raindrop shape: large drops flatten into oblate spheroids (Beard & Chuang 1987).
#pragma once

namespace raintrace::sim {

/// Axis ratio b/a (vertical over horizontal) for an equivalent diameter in metres, in (0, 1].
/// Beard & Chuang's polynomial b/a = 1.0048 + 0.0057·D − 2.628·D² + 3.682·D³ − 1.677·D⁴
/// (D in cm), capped at 1 because it slightly exceeds 1 for D below about 0.5 mm where drops
/// are spheres; valid up to about 9 mm, clamped beyond.
double axis_ratio(double diameter_m);

}  // namespace raintrace::sim
