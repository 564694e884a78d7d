// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 80.630376, 0.000000>
  direction <0.000000, -1936.225014, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <23.479113, 80.052970, -15.675772> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <26.548311, 80.052970, -9.601343> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <28.074617, 80.052970, -2.968919> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <27.969328, 80.052970, 3.836048> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <26.238564, 80.052970, 10.418078> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <22.982909, 80.052970, 16.394647> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <18.391572, 80.052970, 21.418419> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <12.731383, 80.052970, 25.197430> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <6.331293, 80.052970, 27.512057> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-0.436749, 80.052970, 28.227785> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-7.179409, 80.052970, 27.303016> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-13.504828, 80.052970, 24.791495> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-19.045395, 80.052970, 20.839182> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-23.479113, 80.052970, 15.675772> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-26.548311, 80.052970, 9.601343> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-28.074617, 80.052970, 2.968919> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-27.969328, 80.052970, -3.836048> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-26.238564, 80.052970, -10.418078> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-22.982909, 80.052970, -16.394647> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-18.391572, 80.052970, -21.418419> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-12.731383, 80.052970, -25.197430> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <-6.331293, 80.052970, -27.512057> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <0.436749, 80.052970, -28.227785> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <7.179409, 80.052970, -27.303016> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <13.504828, 80.052970, -24.791495> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
light_source { <19.045395, 80.052970, -20.839182> rgb 0.0769231 fade_distance 73.1324 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.0332619 scale <0.274829, 0.0172469, 0.0172469> rotate y * 45.853 translate <23.816238, 23.198580, -16.941564> }
  finish { ambient 0 emission 0 diffuse 0.513224 specular 0.280311 roughness 0.0303021 metallic reflection { 0.0681011 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 0.618633 scallop_wave scale 0.11543 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.0879981 specular 0.638092 roughness 0.00761679 metallic reflection { 0.387604 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.346215 sine_wave scale 0.0706038 translate <23.816238, 23.198580, -16.941564> }
  finish { ambient 0 emission 0 diffuse 0.893063 specular 0.154923 roughness 0.0972685 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.612996, 0.612996, 0.600480> }
  normal { bumps 0.226337 scale 0.165326 translate <23.816238, 23.198580, -16.941564> }
  finish { ambient 0 emission 0 diffuse 0.691956 specular 0.0684585 roughness 0.175233 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.64997 * (1 + 0.00508564 * cos(2 * atan2(z, x) + 6.27804) + 0.000636748 * cos(3 * atan2(z, x) + 4.55885)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.36903
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.36903, 7.5>
    <6.48237, 7.46201>
    <6.56727, 7.3721>
    <6.63142, 7.26312>
    <6.68644, 7.14809>
    <6.73999, 7.03222>
    <6.78932, 6.91419>
    <6.83659, 6.79518>
    <6.88052, 6.67467>
    <6.92148, 6.55295>
    <6.96026, 6.4304>
    <6.99665, 6.307>
    <7.03079, 6.18286>
    <7.06265, 6.058>
    <7.09243, 5.93255>
    <7.12012, 5.80654>
    <7.14577, 5.68002>
    <7.16964, 5.5531>
    <7.19141, 5.42574>
    <7.21153, 5.29806>
    <7.22964, 5.17002>
    <7.24614, 5.04173>
    <7.26104, 4.91321>
    <7.27415, 4.78447>
    <7.28583, 4.65555>
    <7.2956, 4.52646>
    <7.30397, 4.39724>
    <7.31065, 4.26791>
    <7.31592, 4.13851>
    <7.31973, 4.00904>
    <7.32196, 3.87953>
    <7.32302, 3.75>
    <7.32196, 3.62047>
    <7.31973, 3.49096>
    <7.31592, 3.36149>
    <7.31065, 3.23209>
    <7.30397, 3.10276>
    <7.2956, 2.97354>
    <7.28583, 2.84445>
    <7.27415, 2.71553>
    <7.26104, 2.58679>
    <7.24614, 2.45827>
    <7.22964, 2.32998>
    <7.21153, 2.20194>
    <7.19141, 2.07426>
    <7.16964, 1.9469>
    <7.14577, 1.81998>
    <7.12012, 1.69346>
    <7.09243, 1.56745>
    <7.06265, 1.442>
    <7.03079, 1.31714>
    <6.99665, 1.193>
    <6.96026, 1.0696>
    <6.92148, 0.947055>
    <6.88052, 0.825334>
    <6.83659, 0.704822>
    <6.78932, 0.585813>
    <6.73999, 0.467775>
    <6.68644, 0.351915>
    <6.63142, 0.236884>
    <6.56727, 0.127897>
    <6.48237, 0.0379863>
    <6.36903, 0>
    texture { Barrel } }
  matrix <1.00031, 0, -0.00161227, 0, 1, 0, -0.00161227, 0, 0.999692, -0.203427, 0, -0.506179>
}
plane { y, 0 texture { Fixture } }
