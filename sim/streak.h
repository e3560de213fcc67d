// The streak a falling drop leaves on one exposure: its length (paper eq. 3) and how opaque it
// is (Garg & Nayar, "Photorealistic rendering of rain streaks", SIGGRAPH 2006, §3; "Vision and
// rain", IJCV 2007, §4): a drop covers each point of its streak only while it passes over it,
// for about D/v of the exposure, so the streak's opacity is about D/L of the drop's own and the
// light a drop adds to a frame does not depend on the exposure time.
#pragma once

namespace raintrace::sim {

/// Distance a drop moves during the exposure t: V0·t + a·t²/2, never negative (a decelerating
/// drop does not move backwards within one exposure). Metres.
double streak_travel(double speed_m_per_s, double accel_m_per_s2, double exposure_s);

/// L = V0·t + a·t²/2 + 2R: distance covered during the exposure t plus the drop's own
/// diameter (a drop shows as a disk even for t = 0). speed_m_per_s is V0, accel_m_per_s2 the
/// acceleration along the motion, exposure_s is t and diameter_m is 2R. Metres, >= 2R.
double streak_length(double speed_m_per_s, double accel_m_per_s2, double exposure_s,
                     double diameter_m);

/// Share of the exposure during which the drop covers a point of its streak: the streak's
/// opacity there, for a drop that is itself opaque (a drop replaces what lies behind it by what
/// it refracts). The drop's outline is a disc of diameter D moving `travel_m` along the streak;
/// `along_m` runs from the streak's trailing end (0) to its leading end (travel + D), `across_m`
/// from its axis. Inside the streak's middle it is min(1, D'/travel) for the chord D' of the
/// disc at that offset; it ramps to 0 over one chord at each end. Over the whole streak it
/// integrates to the disc's area πD²/4 for any travel: the exposure spreads, never adds, light.
double streak_time_coverage(double along_m, double across_m, double travel_m, double diameter_m);

/// Opacity along the middle of a streak: min(1, D / travel); 1 for a drop that does not move.
double streak_opacity(double travel_m, double diameter_m);

}  // namespace raintrace::sim
