// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 100.788165, 0.000000>
  direction <0.000000, -2118.386869, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <17.083120, 99.294977, -0.100928> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <16.087401, 99.294977, 5.747930> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <13.151304, 99.294977, 10.903503> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <8.628966, 99.294977, 14.743952> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <3.065847, 99.294977, 16.806063> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <-2.867058, 99.294977, 16.841115> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <-8.454154, 99.294977, 14.844880> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <-13.021554, 99.294977, 11.058133> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <-16.018363, 99.294977, 5.937612> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <-17.083120, 99.294977, 0.100928> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <-16.087401, 99.294977, -5.747930> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <-13.151304, 99.294977, -10.903503> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <-8.628966, 99.294977, -14.743952> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <-3.065847, 99.294977, -16.806063> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <2.867058, 99.294977, -16.841115> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <8.454154, 99.294977, -14.844880> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <13.021554, 99.294977, -11.058133> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
light_source { <16.018363, 99.294977, -5.937612> rgb 0.111111 fade_distance 93.3974 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { bumps 0.0985777 scale <0.230198, 0.0128228, 0.0128228> rotate y * 144.612 translate <18.517053, -49.594859, -32.815058> }
  finish { ambient 0 emission 0 diffuse 0.596886 specular 0.253628 roughness 0.04863 metallic }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { onion 0.486327 scallop_wave scale 0.135589 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.554952 specular 0.252737 roughness 0.0571291 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { gradient y 0.144946 sine_wave scale 0.0920817 translate <18.517053, -49.594859, -32.815058> }
  finish { ambient 0 emission 0 diffuse 0.339587 specular 0.121313 roughness 0.0557527 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.345122, 0.233577, 0.197838> }
  finish { ambient 0 emission 0 diffuse 0.440511 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.853126 FaceClean] [0.873126 Stain] [1 Stain] }
  scale 0.897629 translate <31.478989, -84.311261, -55.785599> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.853126 RingClean] [0.873126 Stain] [1 Stain] }
  scale 0.897629 translate <31.478989, -84.311261, -55.785599> }
#declare Fixture = texture {
  pigment { rgb <0.045085, 0.045085, 0.044997> }
  normal { bumps 0.302266 scale 0.248931 translate <18.517053, -49.594859, -32.815058> }
  finish { ambient 0 emission 0 diffuse 0.680431 specular 0.132189 roughness 0.113934 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.20389 * (1 + 0.00283685 * cos(2 * atan2(z, x) + 2.2566) + 0.00456755 * cos(3 * atan2(z, x) + 5.02195)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.25212
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.25212, 7.5>
    <6.35774, 7.4269>
    <6.43768, 7.32621>
    <6.50963, 7.21889>
    <6.57661, 7.10831>
    <6.63917, 6.99513>
    <6.69892, 6.88047>
    <6.75536, 6.76416>
    <6.809, 6.64655>
    <6.86004, 6.52778>
    <6.90878, 6.40805>
    <6.95409, 6.287>
    <6.99713, 6.16511>
    <7.03789, 6.04245>
    <7.07618, 5.91899>
    <7.11203, 5.7948>
    <7.14539, 5.66993>
    <7.17619, 5.54439>
    <7.20491, 5.41835>
    <7.2315, 5.29185>
    <7.25577, 5.16487>
    <7.27774, 5.03748>
    <7.29724, 4.90967>
    <7.31483, 4.78159>
    <7.33038, 4.65325>
    <7.34378, 4.52465>
    <7.35527, 4.39586>
    <7.36411, 4.26687>
    <7.37121, 4.13776>
    <7.37627, 4.00856>
    <7.37935, 3.8793>
    <7.38079, 3.75>
    <7.37935, 3.6207>
    <7.37627, 3.49144>
    <7.37121, 3.36224>
    <7.36411, 3.23313>
    <7.35527, 3.10414>
    <7.34378, 2.97535>
    <7.33038, 2.84675>
    <7.31483, 2.71841>
    <7.29724, 2.59033>
    <7.27774, 2.46252>
    <7.25577, 2.33513>
    <7.2315, 2.20815>
    <7.20491, 2.08165>
    <7.17619, 1.95561>
    <7.14539, 1.83007>
    <7.11203, 1.7052>
    <7.07618, 1.58101>
    <7.03789, 1.45755>
    <6.99713, 1.33489>
    <6.95409, 1.213>
    <6.90878, 1.09195>
    <6.86004, 0.972218>
    <6.809, 0.853451>
    <6.75536, 0.735836>
    <6.69892, 0.619527>
    <6.63917, 0.504866>
    <6.57661, 0.391687>
    <6.50963, 0.281107>
    <6.43768, 0.173786>
    <6.35774, 0.0730952>
    <6.25212, 0>
    texture { Barrel } }
  matrix <1.00061, 0, -0.00574751, 0, 1, 0, -0.00574751, 0, 0.999428, 4.30118, 0, 1.37739>
}
plane { y, 0 texture { Fixture } }
