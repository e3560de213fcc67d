// peer_rain.pov — rain the way POV-Ray users make it today, for comparison with raintrace
// (bench/render_compare.sh). An SDL #while loop with rand() fills a box that covers the
// camera's view with drops: each a small sphere stretched along y to fake motion blur, with a
// semi-transparent watery texture, all in one union. Same camera, size and drop density as
// examples/heavy_rain.toml (50 mm/h: Marshall-Palmer gives about 1 800 drops/m³) and the same
// night_street environment, so the two render times compare like with like.
//   povray peer_rain.pov +L<raintrace output folder> +W640 +H360 -D -A
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 32 }
#declare RT_Mask = 0;
#declare RT_Flash = 0;
camera { perspective location <0, 1.6, -5> look_at <0, 1.3, 0> right x*16/9 up y angle 60 }
// The environment raintrace writes into every output folder (found through +L).
#include "environment.inc"

// The box in front of the camera out to 5 m (heavy_rain's far_m): at depth 5 m the view is
// 2·5·tan 30° = 5.77 m wide and 3.25 m high around the view axis.
#declare Box_Min = <-2.9, -0.1, -4.7>;
#declare Box_Max = <2.9, 3.3, 0.0>;
#declare Density = 1800;  // drops per m³
#declare Size = Box_Max - Box_Min;
#declare Count = int(Density * Size.x * Size.y * Size.z);
#declare Stream = seed(7);
#declare T_Rain = texture {
  pigment { rgbf <0.9, 0.95, 1, 0.8> }
  finish { ambient 0.05 diffuse 0.6 specular 0.5 roughness 0.01 }
}
union {
  #declare I = 0;
  #while (I < Count)
    #declare Radius = 0.0003 + 0.0012 * rand(Stream);
    // Stretched 40× along y: a drop's 18 cm streak over a 1/50 s exposure at 9 m/s.
    sphere {
      0, Radius scale <1, 40, 1>
      translate Box_Min + <rand(Stream) * Size.x, rand(Stream) * Size.y, rand(Stream) * Size.z>
    }
    #declare I = I + 1;
  #end
  texture { T_Rain }
  no_shadow hollow
}
