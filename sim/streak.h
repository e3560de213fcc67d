// Length of the streak a falling drop leaves on one exposure (paper eq. 3).
#pragma once

namespace raintrace::sim {

/// L = V0·t + a·t²/2 + 2R: distance covered during the exposure t plus the drop's own
/// diameter (a drop shows as a disk even for t = 0). speed_m_per_s is V0, accel_m_per_s2 the
/// acceleration along the motion, exposure_s is t and diameter_m is 2R. Metres, >= 2R.
double streak_length(double speed_m_per_s, double accel_m_per_s2, double exposure_s,
                     double diameter_m);

}  // namespace raintrace::sim
