// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 99.870058, 0.000000>
  direction <0.000000, -2355.026265, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-15.969179, 93.052072, 9.785697> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <-18.079265, 93.052072, 4.890270> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <-18.724676, 93.052072, -0.401338> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <-17.853125, 93.052072, -5.660432> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <-15.535220, 93.052072, -10.460951> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <-11.958744, 93.052072, -14.413986> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <-7.413441, 93.052072, -17.199286> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <-2.267546, 93.052072, -18.591202> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <3.062052, 93.052072, -18.476969> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <8.143581, 93.052072, -16.865842> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <12.565366, 93.052072, -13.888345> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <15.969179, 93.052072, -9.785697> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <18.079265, 93.052072, -4.890270> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <18.724676, 93.052072, 0.401338> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <17.853125, 93.052072, 5.660432> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <15.535220, 93.052072, 10.460951> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <11.958744, 93.052072, 14.413986> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <7.413441, 93.052072, 17.199286> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <2.267546, 93.052072, 18.591202> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <-3.062052, 93.052072, 18.476969> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <-8.143581, 93.052072, 16.865842> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
light_source { <-12.565366, 93.052072, 13.888345> rgb 0.0909091 fade_distance 92.3726 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { bumps 0.0833376 scale <0.228657, 0.0117378, 0.0117378> rotate y * 44.6376 translate <-10.586780, -48.953260, -30.765828> }
  finish { ambient 0 emission 0 diffuse 0.755479 specular 0.48047 roughness 0.0504614 metallic reflection { 0.0837008 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { onion 1.19326 scallop_wave scale 0.172343 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.28604 specular 0.051365 roughness 0.0824185 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { gradient y 0.215568 sine_wave scale 0.104717 translate <-10.586780, -48.953260, -30.765828> }
  finish { ambient 0 emission 0 diffuse 0.388127 specular 0.128458 roughness 0.0922998 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.360185, 0.290445, 0.214432> }
  finish { ambient 0 emission 0 diffuse 0.645941 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.95256 FaceClean] [0.97256 Stain] [1 Stain] }
  scale 1.19346 translate <-17.997526, -83.220542, -52.301907> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.95256 RingClean] [0.97256 Stain] [1 Stain] }
  scale 1.19346 translate <-17.997526, -83.220542, -52.301907> }
#declare Fixture = texture {
  pigment { rgb <0.576264, 0.576264, 0.580757> }
  normal { bumps 0.290583 scale 0.144988 translate <-10.586780, -48.953260, -30.765828> }
  finish { ambient 0 emission 0 diffuse 0.799331 specular 0.144828 roughness 0.0571511 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.29585 * (1 + 0.00945398 * cos(2 * atan2(z, x) + 2.93015) + 0.00319425 * cos(3 * atan2(z, x) + 2.35794)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.57748
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.57748, 7.5>
    <6.67187, 7.42313>
    <6.74129, 7.32011>
    <6.79168, 7.20611>
    <6.83263, 7.08857>
    <6.86906, 6.96932>
    <6.90299, 6.84955>
    <6.9347, 6.72884>
    <6.96316, 6.60739>
    <6.98998, 6.48549>
    <7.01396, 6.36298>
    <7.0364, 6.24015>
    <7.05703, 6.11698>
    <7.07608, 5.99353>
    <7.09352, 5.86982>
    <7.1096, 5.74592>
    <7.1243, 5.62182>
    <7.13773, 5.49757>
    <7.15009, 5.3732>
    <7.16111, 5.24869>
    <7.17132, 5.12411>
    <7.18016, 4.99941>
    <7.18834, 4.87467>
    <7.19525, 4.74983>
    <7.20148, 4.62496>
    <7.2067, 4.50004>
    <7.21115, 4.37509>
    <7.21477, 4.25011>
    <7.2175, 4.1251>
    <7.21959, 4.00008>
    <7.22067, 3.87504>
    <7.2213, 3.75>
    <7.22067, 3.62496>
    <7.21959, 3.49992>
    <7.2175, 3.3749>
    <7.21477, 3.24989>
    <7.21115, 3.12491>
    <7.2067, 2.99996>
    <7.20148, 2.87504>
    <7.19525, 2.75017>
    <7.18834, 2.62533>
    <7.18016, 2.50059>
    <7.17132, 2.37589>
    <7.16111, 2.25131>
    <7.15009, 2.1268>
    <7.13773, 2.00243>
    <7.1243, 1.87818>
    <7.1096, 1.75408>
    <7.09352, 1.63018>
    <7.07608, 1.50647>
    <7.05703, 1.38302>
    <7.0364, 1.25985>
    <7.01396, 1.13702>
    <6.98998, 1.01451>
    <6.96316, 0.892606>
    <6.9347, 0.771164>
    <6.90299, 0.650453>
    <6.86906, 0.530681>
    <6.83263, 0.411432>
    <6.79168, 0.293889>
    <6.74129, 0.179886>
    <6.67187, 0.0768729>
    <6.57748, 0>
    texture { Barrel } }
  matrix <1.00443, 0, -0.00175769, 0, 1, 0, -0.00175769, 0, 0.995592, 0.09375, 0, 0.675092>
}
plane { y, 0 texture { Fixture } }
