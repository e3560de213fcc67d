// Shape of a falling drop and the length of its streak on an exposed image, in the units the
// exporter uses (radius). Delegates to sim/ so simulation and picture share one formula.
#pragma once

namespace raintrace::povgen {

/// Axis ratio b/a (vertical over horizontal) of a drop of equivalent-volume diameter
/// `diameter_m`, from Beard & Chuang (1987)'s fit
///   b/a = 1.0048 + 0.0057·D − 2.628·D² + 3.682·D³ − 1.677·D⁴   (D in cm),
/// clamped to [0.5, 1] (drops past ~8 mm break up before they flatten further).
double drop_axis_ratio(double diameter_m);

/// Length of the streak a drop leaves during an exposure (paper eq. 3):
///   L = V0·t + a·t²/2 + 2R
/// speed_m_per_s = V0 along the motion, accel_m_per_s2 = a along the motion, exposure_s = t,
/// radius_m = R. Never shorter than the drop itself (2R), whatever the sign of a.
double streak_length(double speed_m_per_s, double accel_m_per_s2, double exposure_s,
                     double radius_m);

}  // namespace raintrace::povgen
