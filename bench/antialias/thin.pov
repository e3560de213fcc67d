// Sub-pixel bright lamp rims against antialiasing (BENCHMARKS.md, "Antialiasing at final quality
// on HDR frames"): three slanted bars at radiance 300 on a 0.02 background, 0.3, 0.1 and 0.03
// pixels wide at +W64 +H64. Each pixel a bar crosses should develop to white or nearly (coverage
// × 300 = 90, 30, 9; Filmic is white from 16.29, 9 shows at 0.99).
// Render with -A, +A0.1 +AM1 +R3 -J, +A0.0 +R3, +A0.0 +R5 (all +FE) and develop to compare.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-5> look_at <0,0,0> right x*2 up y*2 }
background { rgb 0.02 }
#declare P = 2/64;
box { <-1.2,-0.3*P/2,0>, <1.2,0.3*P/2,0.1> rotate z*7 translate y*0.5 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 300 } }
box { <-1.2,-0.1*P/2,0>, <1.2,0.1*P/2,0.1> rotate z*7 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 300 } }
box { <-1.2,-0.03*P/2,0>, <1.2,0.03*P/2,0.1> rotate z*7 translate -y*0.5 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 300 } }
