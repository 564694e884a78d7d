// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 52.749083, 0.000000>
  direction <0.000000, -1122.748950, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <17.139124, 50.575919, -7.543566> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <18.306794, 50.575919, -3.939069> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <18.724981, 50.575919, -0.173305> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <18.376566, 50.575919, 3.599553> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <17.275812, 50.575919, 7.225046> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <15.467784, 50.575919, 10.554744> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <13.026503, 50.575919, 13.452330> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <10.051916, 50.575919, 15.799176> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <6.665802, 50.575919, 17.499201> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <3.006789, 50.575919, 18.482808> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-0.775322, 50.575919, 18.709726> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-4.525691, 50.575919, 18.170666> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-8.090778, 50.575919, 16.887696> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-11.324627, 50.575919, 14.913342> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-14.094845, 50.575919, 12.328435> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-16.288019, 50.575919, 9.238799> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-17.814359, 50.575919, 5.770926> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-18.611377, 50.575919, 2.066791> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-18.646443, 50.575919, -1.721959> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-17.918121, 50.575919, -5.440211> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-16.456230, 50.575919, -8.935741> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-14.320618, 50.575919, -12.065441> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-11.598719, 50.575919, -14.701180> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-8.401967, 50.575919, -16.735051> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-4.861237, 50.575919, -18.083787> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <-1.121488, 50.575919, -18.692170> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <2.664175, 50.575919, -18.535294> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <6.340767, 50.575919, -17.619581> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <9.757767, 50.575919, -15.982520> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <12.775282, 50.575919, -13.691133> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
light_source { <15.269776, 50.575919, -10.839230> rgb 0.0645161 fade_distance 45.2562 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { bumps 0.104129 scale <0.620651, 0.035468, 0.035468> rotate y * 157.241 translate <36.820912, 49.331094, 38.524057> }
  finish { ambient 0 emission 0 diffuse 0.621851 specular 0.386244 roughness 0.059995 metallic reflection { 0.005665 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { onion 1.29107 scallop_wave scale 0.165145 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.261153 specular 0.153844 roughness 0.0978388 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { gradient y 0.130465 sine_wave scale 0.106279 translate <36.820912, 49.331094, 38.524057> }
  finish { ambient 0 emission 0 diffuse 0.40575 specular 0.0690514 roughness 0.0555599 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.316192, 0.237296, 0.225916> }
  finish { ambient 0 emission 0 diffuse 0.359223 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.851007 FaceClean] [0.871007 Stain] [1 Stain] }
  scale 0.87927 translate <62.595551, 83.862860, 65.490898> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.851007 RingClean] [0.871007 Stain] [1 Stain] }
  scale 0.87927 translate <62.595551, 83.862860, 65.490898> }
#declare Fixture = texture {
  pigment { rgb <0.060479, 0.060479, 0.059709> }
  normal { bumps 0.175489 scale 0.292827 translate <36.820912, 49.331094, 38.524057> }
  finish { ambient 0 emission 0 diffuse 0.836545 specular 0.0269118 roughness 0.0839983 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.95204 * (1 + 0.00102148 * cos(2 * atan2(z, x) + 3.3961) + 0.00206881 * cos(3 * atan2(z, x) + 3.57965)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.45358
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.45358, 7.5>
    <6.56151, 7.48542>
    <6.63862, 7.46025>
    <6.69774, 7.43129>
    <6.74999, 7.40053>
    <6.79752, 7.36843>
    <6.84324, 7.33515>
    <6.88331, 7.30031>
    <6.92168, 7.26422>
    <6.95631, 7.22659>
    <6.9882, 7.18743>
    <7.01795, 7.14669>
    <7.04539, 7.10423>
    <7.07079, 7.05992>
    <7.09417, 7.01359>
    <7.11575, 6.96506>
    <7.13537, 6.91408>
    <7.15348, 6.86039>
    <7.16992, 6.80366>
    <7.18492, 6.74348>
    <7.19859, 6.67935>
    <7.21073, 6.61061>
    <7.2218, 6.53646>
    <7.23127, 6.45577>
    <7.23971, 6.36708>
    <7.24676, 6.26825>
    <7.25282, 6.15614>
    <7.2577, 6.02566>
    <7.26147, 5.86778>
    <7.26425, 5.66367>
    <7.26581, 5.35921>
    <7.26659, 3.75>
    <7.26581, 2.14079>
    <7.26425, 1.83633>
    <7.26147, 1.63222>
    <7.2577, 1.47434>
    <7.25282, 1.34386>
    <7.24676, 1.23175>
    <7.23971, 1.13292>
    <7.23127, 1.04423>
    <7.2218, 0.963538>
    <7.21073, 0.889386>
    <7.19859, 0.820646>
    <7.18492, 0.756516>
    <7.16992, 0.696337>
    <7.15348, 0.639607>
    <7.13537, 0.585924>
    <7.11575, 0.534942>
    <7.09417, 0.486411>
    <7.07079, 0.440082>
    <7.04539, 0.39577>
    <7.01795, 0.353307>
    <6.9882, 0.312568>
    <6.95631, 0.273412>
    <6.92168, 0.235781>
    <6.88331, 0.199689>
    <6.84324, 0.164846>
    <6.79752, 0.131575>
    <6.74999, 0.0994653>
    <6.69774, 0.0687068>
    <6.63862, 0.0397477>
    <6.56151, 0.0145778>
    <6.45358, 0>
    texture { Barrel } }
  matrix <0.997669, 0, -0.0038058, 0, 1, 0, -0.0038058, 0, 1.00235, -0.765911, 0, -0.235842>
}
plane { y, 0 texture { Fixture } }
