// How POV-Ray 3.7's adaptive antialiasing treats HDR values (BENCHMARKS.md, "Antialiasing at
// final quality on HDR frames"): an emitting disc of radiance A on a background of B, so every
// row crosses one edge. Render with e.g. +W64 +H64 +A0.1 +AM1 +R3 -J +FE -D Declare=A=300 Declare=B=1.5
// and read POV-Ray's "Samples" statistic (extra samples spent on antialiasing).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (A) #declare A = 1; #end
#ifndef (B) #declare B = 0; #end
camera { orthographic location <0,0,-5> look_at <0,0,0> right x*2 up y*2 }
background { rgb B }
disc { <0,0,0>, -z, 0.7 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission A } }
