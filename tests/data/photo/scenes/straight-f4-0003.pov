// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 96.004295, 0.000000>
  direction <0.000000, -2389.832333, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-32.610952, 88.830836, 3.143750> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <-32.088775, 88.830836, -6.608165> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <-28.715370, 88.830836, -15.772915> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <-22.790478, 88.830836, -23.536173> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <-14.840553, 88.830836, -29.208138> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <-5.571979, 88.830836, -32.284832> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <4.191690, 88.830836, -32.492877> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <13.582909, 88.830836, -29.813787> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <21.767226, 88.830836, -24.485612> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <28.017430, 88.830836, -16.981782> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <31.778163, 88.830836, -7.969047> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <32.715266, 88.830836, 1.751774> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <30.745474, 88.830836, 11.316941> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <26.043812, 88.830836, 19.876549> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <19.028043, 88.830836, 26.670038> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <10.321549, 88.830836, 31.093777> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <0.697940, 88.830836, 32.754698> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <-8.987684, 88.830836, 31.505220> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <-17.874713, 88.830836, 27.456365> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <-25.173495, 88.830836, 20.967891> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
light_source { <-30.235502, 88.830836, 12.616328> rgb 0.0952381 fade_distance 88.508 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { bumps 0.0314997 scale <0.249405, 0.0194856, 0.0194856> rotate y * 127.673 translate <22.668489, 46.758758, 9.319075> }
  finish { ambient 0 emission 0 diffuse 0.524896 specular 0.140413 roughness 0.0750791 metallic reflection { 0.0708411 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { onion 0.455597 scallop_wave scale 0.174098 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.0654352 specular 0.577296 roughness 0.0103214 metallic reflection { 0.382033 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { gradient y 0.308042 sine_wave scale 0.1187 translate <22.668489, 46.758758, 9.319075> }
  finish { ambient 0 emission 0 diffuse 0.627462 specular 0.224721 roughness 0.119099 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.461341, 0.461341, 0.454506> }
  normal { bumps 0.15184 scale 0.29164 translate <22.668489, 46.758758, 9.319075> }
  finish { ambient 0 emission 0 diffuse 0.891803 specular 0.088637 roughness 0.17101 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.43161 * (1 + 0.0046498 * cos(2 * atan2(z, x) + 1.27466) + 0.00447118 * cos(3 * atan2(z, x) + 6.02724)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.30702
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.30702, 7.5>
    <6.42128, 7.48846>
    <6.51089, 7.46647>
    <6.58334, 7.43922>
    <6.6482, 7.40975>
    <6.70923, 7.37891>
    <6.76465, 7.34636>
    <6.81666, 7.31241>
    <6.86506, 7.27697>
    <6.90999, 7.23996>
    <6.95198, 7.20137>
    <6.99147, 7.16114>
    <7.02713, 7.11899>
    <7.0608, 7.07498>
    <7.0919, 7.02889>
    <7.1206, 6.98051>
    <7.14725, 6.92966>
    <7.17164, 6.87603>
    <7.19379, 6.81928>
    <7.214, 6.75903>
    <7.23232, 6.69477>
    <7.24887, 6.62585>
    <7.2637, 6.55146>
    <7.27684, 6.47048>
    <7.28838, 6.38142>
    <7.29804, 6.28214>
    <7.30624, 6.16947>
    <7.31285, 6.03832>
    <7.31802, 5.87961>
    <7.32174, 5.67438>
    <7.32398, 5.36823>
    <7.32493, 3.75>
    <7.32398, 2.13177>
    <7.32174, 1.82562>
    <7.31802, 1.62039>
    <7.31285, 1.46168>
    <7.30624, 1.33053>
    <7.29804, 1.21786>
    <7.28838, 1.11858>
    <7.27684, 1.02952>
    <7.2637, 0.948543>
    <7.24887, 0.874146>
    <7.23232, 0.805229>
    <7.214, 0.740966>
    <7.19379, 0.680716>
    <7.17164, 0.62397>
    <7.14725, 0.570338>
    <7.1206, 0.519487>
    <7.0919, 0.471113>
    <7.0608, 0.425016>
    <7.02713, 0.381008>
    <6.99147, 0.338863>
    <6.95198, 0.298627>
    <6.90999, 0.260036>
    <6.86506, 0.223032>
    <6.81666, 0.187589>
    <6.76465, 0.153638>
    <6.70923, 0.121093>
    <6.6482, 0.0902464>
    <6.58334, 0.0607818>
    <6.51089, 0.0335307>
    <6.42128, 0.0115435>
    <6.30702, 0>
    texture { Barrel } }
  matrix <0.997602, 0, -8.77516e-05, 0, 1, 0, -8.77516e-05, 0, 1.0024, -0.793877, 0, 0.171737>
}
plane { y, 0 texture { Fixture } }
