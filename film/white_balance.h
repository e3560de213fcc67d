// White balance: the camera's choice of which light shows as white. A frame is traced in linear
// sRGB with D65 as white, so a street lit by 3000 K lamps comes out orange, as it does from a
// camera set to daylight. A camera balanced for the scene's light multiplies its red, green and
// blue by gains that turn light of that colour temperature grey: a cinematographer balances for
// the practical lights, and then the other lights of a mixed street keep their hues (a 4000 K
// LED cooler, a sodium lamp orange, a white sign blue). Applied first, in scene-linear light, as
// a camera applies it to the sensor's raw signal.
//
// Colour temperatures are blackbodies on the CIE 1931 2° observer's Planckian locus: Kim et
// al.'s cubic fit of its chromaticity (Kim, Lee, Cho and Kwak, "Design of advanced color
// temperature control system for HDTV applications", J. Korean Physical Society 41(6), 2002),
// 1667–25 000 K, within 0.001 of the locus's x and y; then IEC 61966-2-1's matrix from XYZ to
// linear sRGB.
#pragma once

#include <array>

#include "film/rgb_image.h"

namespace raintrace::film {

/// Warmest and coolest balance accepted, K. At 2000 K a blackbody's blue in linear sRGB is
/// already under 1 % of its red (a blue gain of 50), and below 1900 K it leaves sRGB's gamut.
inline constexpr double kMinWhiteBalanceK = 2000.0;
inline constexpr double kMaxWhiteBalanceK = 20000.0;

/// CIE 1931 chromaticity (x, y) of a blackbody at `kelvin`, in [1667, 25000] (Kim et al.'s fit).
/// Throws std::invalid_argument outside it.
std::array<double, 2> blackbody_chromaticity(double kelvin);

/// Linear sRGB (D65 white) of a blackbody at `kelvin`, scaled to luminance 1
/// (0.2126 R + 0.7152 G + 0.0722 B): e.g. 3000 K ≈ (1.77, 0.85, 0.27). Throws
/// std::invalid_argument outside [1667, 25000] K, or where the colour leaves sRGB's gamut.
std::array<double, 3> blackbody_rgb(double kelvin);

/// Multiplies R, G and B by 1 / blackbody_rgb(kelvin): light of that temperature becomes grey of
/// the same luminance. 0 = off (D65 stays white: the frame as traced). Throws
/// std::invalid_argument for anything else outside [kMinWhiteBalanceK, kMaxWhiteBalanceK].
void apply_white_balance(RgbImage& image, double kelvin);

}  // namespace raintrace::film
