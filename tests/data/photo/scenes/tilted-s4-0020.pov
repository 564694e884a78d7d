// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <10.860745, 72.906267, -0.575266>
  direction <-287.895376, -1598.796353, 38.325762>
  right <629.873869, -113.389119, 1.348030>
  up <1.011023, 11.321103, 479.865409> }
light_source { <19.736486, 64.153543, 12.371714> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <12.106996, 65.609618, 15.802127> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <3.794906, 67.084527, 14.890648> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <-2.972568, 68.183069, 9.881506> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <-6.382086, 68.610891, 2.116896> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <-5.520071, 68.253358, -6.322660> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <-0.617498, 67.206271, -13.175790> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <7.011992, 65.750195, -16.606203> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <15.324082, 64.275286, -15.694724> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <22.091556, 63.176744, -10.685582> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <25.501074, 62.748922, -2.920972> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
light_source { <24.639059, 63.106455, 5.518583> rgb 0.166667 fade_distance 66.3043 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { bumps 0.0627448 scale <0.691161, 0.0372594, 0.0372594> rotate y * 7.70944 translate <-5.674003, 5.937794, -39.982725> }
  finish { ambient 0 emission 0 diffuse 0.384134 specular 0.261879 roughness 0.0620138 metallic }
}
#declare RingClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { onion 0.316354 scallop_wave scale 0.165149 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.354597 specular 0.164158 roughness 0.0679972 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { gradient y 0.227161 sine_wave scale 0.0964832 translate <-5.674003, 5.937794, -39.982725> }
  finish { ambient 0 emission 0 diffuse 0.504471 specular 0.157195 roughness 0.0713749 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.327369, 0.252722, 0.216744> }
  finish { ambient 0 emission 0 diffuse 0.577801 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.911951 FaceClean] [0.931951 Stain] [1 Stain] }
  scale 0.592242 translate <-9.645805, 10.094251, -67.970633> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.911951 RingClean] [0.931951 Stain] [1 Stain] }
  scale 0.592242 translate <-9.645805, 10.094251, -67.970633> }
#declare Fixture = texture {
  pigment { rgb <0.616982, 0.616982, 0.610067> }
  normal { bumps 0.307451 scale 0.19185 translate <-5.674003, 5.937794, -39.982725> }
  finish { ambient 0 emission 0 diffuse 0.67027 specular 0.0297358 roughness 0.067506 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.53494 * (1 + 0.00791591 * cos(2 * atan2(z, x) + 0.214594) + 0.00221808 * cos(3 * atan2(z, x) + 5.20538)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.34102
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.34102, 7.5>
    <6.43825, 7.41905>
    <6.50952, 7.31397>
    <6.56841, 7.20111>
    <6.62519, 7.08702>
    <6.67978, 6.97177>
    <6.73228, 6.85558>
    <6.78277, 6.73843>
    <6.83057, 6.62016>
    <6.8766, 6.50118>
    <6.9206, 6.38143>
    <6.96246, 6.26089>
    <7.00211, 6.13959>
    <7.03978, 6.01766>
    <7.07544, 5.8951>
    <7.1088, 5.77189>
    <7.14034, 5.64819>
    <7.16944, 5.52387>
    <7.19658, 5.3991>
    <7.22183, 5.27393>
    <7.24486, 5.14832>
    <7.26601, 5.02237>
    <7.28473, 4.89602>
    <7.30162, 4.76941>
    <7.31662, 4.64256>
    <7.3295, 4.51546>
    <7.34064, 4.3882>
    <7.34922, 4.26073>
    <7.35611, 4.13315>
    <7.36102, 4.00549>
    <7.36401, 3.87776>
    <7.36542, 3.75>
    <7.36401, 3.62224>
    <7.36102, 3.49451>
    <7.35611, 3.36685>
    <7.34922, 3.23927>
    <7.34064, 3.1118>
    <7.3295, 2.98454>
    <7.31662, 2.85744>
    <7.30162, 2.73059>
    <7.28473, 2.60398>
    <7.26601, 2.47763>
    <7.24486, 2.35168>
    <7.22183, 2.22607>
    <7.19658, 2.1009>
    <7.16944, 1.97613>
    <7.14034, 1.85181>
    <7.1088, 1.72811>
    <7.07544, 1.6049>
    <7.03978, 1.48234>
    <7.00211, 1.36041>
    <6.96246, 1.23911>
    <6.9206, 1.11857>
    <6.8766, 0.998817>
    <6.83057, 0.879841>
    <6.78277, 0.761573>
    <6.73228, 0.644424>
    <6.67978, 0.528234>
    <6.62519, 0.412982>
    <6.56841, 0.298891>
    <6.50952, 0.186032>
    <6.43825, 0.0809469>
    <6.34102, 0>
    texture { Barrel } }
  matrix <0.999598, 0, -0.000170272, 0, 1, 0, -0.000170272, 0, 1.0004, 0, 0, 0>
}
plane { y, 0 texture { Fixture } }
