// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 54.788761, 0.000000>
  direction <0.000000, -1010.895418, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <21.864025, 48.514164, 21.699049> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <15.198914, 48.514164, 26.793233> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <7.406569, 48.514164, 29.900285> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-0.935087, 48.514164, 30.789770> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-9.207392, 48.514164, 29.395718> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-16.796827, 48.514164, 25.821521> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-23.140518, 48.514164, 20.332259> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-27.767982, 48.514164, 13.335047> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-30.336023, 48.514164, 5.348835> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-30.654179, 48.514164, -3.034075> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-28.698855, 48.514164, -11.191962> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-24.615069, 48.514164, -18.519792> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-18.705695, 48.514164, -24.474094> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-11.409006, 48.514164, -28.613265> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <-3.266162, 48.514164, -30.630320> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <5.118917, 48.514164, -30.375665> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <13.124350, 48.514164, -27.868185> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <20.156410, 48.514164, -23.293850> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <25.693561, 48.514164, -16.991917> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <29.325138, 48.514164, -9.429770> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <30.781804, 48.514164, -1.168261> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <29.955525, 48.514164, 7.179892> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
light_source { <26.907581, 48.514164, 14.995546> rgb 0.0869565 fade_distance 47.6225 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.0682181 scale <0.184946, 0.0276202, 0.0276202> rotate y * 109.549 translate <8.431939, 24.016072, 38.987747> }
  finish { ambient 0 emission 0 diffuse 0.592063 specular 0.380359 roughness 0.0562109 metallic reflection { 0.080405 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 1.16924 scallop_wave scale 0.165285 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.067865 specular 0.642608 roughness 0.00908118 metallic reflection { 0.475011 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.354745 sine_wave scale 0.0752232 translate <8.431939, 24.016072, 38.987747> }
  finish { ambient 0 emission 0 diffuse 0.610457 specular 0.236408 roughness 0.0809959 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.264254, 0.245269, 0.248037> }
  finish { ambient 0 emission 0 diffuse 0.627577 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.862333 FaceClean] [0.882333 Stain] [1 Stain] }
  scale 0.916171 translate <14.334296, 40.827323, 66.279170> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.862333 RingClean] [0.882333 Stain] [1 Stain] }
  scale 0.916171 translate <14.334296, 40.827323, 66.279170> }
#declare Fixture = texture {
  pigment { rgb <0.627217, 0.627217, 0.632841> }
  normal { bumps 0.29201 scale 0.103973 translate <8.431939, 24.016072, 38.987747> }
  finish { ambient 0 emission 0 diffuse 0.83585 specular 0.0274833 roughness 0.0823142 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.1323 * (1 + 0.0102002 * cos(2 * atan2(z, x) + 2.14332) + 0.00216384 * cos(3 * atan2(z, x) + 0.498562)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.53442
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.53442, 7.5>
    <6.62688, 7.42724>
    <6.69396, 7.32369>
    <6.74294, 7.20902>
    <6.78289, 7.0905>
    <6.81959, 6.97102>
    <6.85587, 6.85123>
    <6.89056, 6.73095>
    <6.92372, 6.61017>
    <6.95517, 6.48887>
    <6.98489, 6.36709>
    <7.01322, 6.24494>
    <7.03991, 6.12237>
    <7.06515, 5.99946>
    <7.08884, 5.87621>
    <7.1111, 5.75264>
    <7.13182, 5.62878>
    <7.15128, 5.50468>
    <7.16915, 5.38031>
    <7.18567, 5.25572>
    <7.20078, 5.13092>
    <7.21446, 5.00594>
    <7.22696, 4.88081>
    <7.23784, 4.75551>
    <7.24769, 4.63011>
    <7.25591, 4.50457>
    <7.26302, 4.37895>
    <7.26868, 4.25325>
    <7.27315, 4.12749>
    <7.2764, 4.00169>
    <7.27827, 3.87585>
    <7.27921, 3.75>
    <7.27827, 3.62415>
    <7.2764, 3.49831>
    <7.27315, 3.37251>
    <7.26868, 3.24675>
    <7.26302, 3.12105>
    <7.25591, 2.99543>
    <7.24769, 2.86989>
    <7.23784, 2.74449>
    <7.22696, 2.61919>
    <7.21446, 2.49406>
    <7.20078, 2.36908>
    <7.18567, 2.24428>
    <7.16915, 2.11969>
    <7.15128, 1.99532>
    <7.13182, 1.87122>
    <7.1111, 1.74736>
    <7.08884, 1.62379>
    <7.06515, 1.50054>
    <7.03991, 1.37763>
    <7.01322, 1.25506>
    <6.98489, 1.13291>
    <6.95517, 1.01113>
    <6.92372, 0.889834>
    <6.89056, 0.769054>
    <6.85587, 0.648772>
    <6.81959, 0.528984>
    <6.78289, 0.409497>
    <6.74294, 0.29098>
    <6.69396, 0.176313>
    <6.62688, 0.0727587>
    <6.53442, 0>
    texture { Barrel } }
  matrix <0.999048, 0, 0.000603196, 0, 1, 0, 0.000603196, 0, 1.00095, -5.32343, 0, 1.82719>
}
plane { y, 0 texture { Fixture } }
