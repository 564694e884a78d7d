// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 65.278733, 0.000000>
  direction <0.000000, -3230.229235, 0.000000>
  right <1456.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 1088.000000> }
light_source { <14.171729, 64.832051, 11.660434> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <9.617729, 64.832051, 15.630193> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <4.021499, 64.832051, 17.906178> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <-2.010524, 64.832051, 18.241750> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <-7.824674, 64.832051, 16.600546> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <-12.790900, 64.832051, 13.160415> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <-16.371034, 64.832051, 8.294149> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <-18.177112, 64.832051, 2.529083> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <-18.013417, 64.832051, -3.510048> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <-15.897690, 64.832051, -9.168811> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <-12.059201, 64.832051, -13.833991> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <-6.913911, 64.832051, -17.000044> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <-1.019391, 64.832051, -18.323878> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <4.985596, 64.832051, -17.662035> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <10.450316, 64.832051, -15.086237> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <14.782582, 64.832051, -10.875611> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <17.512926, 64.832051, -5.486444> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <18.345473, 64.832051, 0.497265> rgb 0.105263 fade_distance 57.781 fade_power 2 }
light_source { <17.190003, 64.832051, 6.427087> rgb 0.105263 fade_distance 57.781 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { bumps 0.0653437 scale <0.407739, 0.0384701, 0.0384701> rotate y * 132.857 translate <22.085503, -28.878409, 15.191330> }
  finish { ambient 0 emission 0 diffuse 0.474148 specular 0.355871 roughness 0.0317031 metallic reflection { 0.0185255 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { onion 1.01291 scallop_wave scale 0.0707831 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.0923898 specular 0.417669 roughness 0.00786159 metallic reflection { 0.435294 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { gradient y 0.161166 sine_wave scale 0.0595034 translate <22.085503, -28.878409, 15.191330> }
  finish { ambient 0 emission 0 diffuse 0.823103 specular 0.279421 roughness 0.0618075 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.651384, 0.651384, 0.668885> }
  normal { bumps 0.298003 scale 0.132558 translate <22.085503, -28.878409, 15.191330> }
  finish { ambient 0 emission 0 diffuse 0.828014 specular 0.129734 roughness 0.0515683 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.76804 * (1 + 0.0117832 * cos(2 * atan2(z, x) + 1.85254) + 0.0047202 * cos(3 * atan2(z, x) + 4.86218)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.40148
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.40148, 7.5>
    <6.51466, 7.46948>
    <6.59991, 7.38031>
    <6.66571, 7.27296>
    <6.71918, 7.15751>
    <6.7707, 7.04107>
    <6.81865, 6.9228>
    <6.86248, 6.80263>
    <6.90452, 6.68171>
    <6.94236, 6.55912>
    <6.97778, 6.43567>
    <7.01084, 6.31144>
    <7.04155, 6.18649>
    <7.07014, 6.06094>
    <7.09673, 5.93487>
    <7.12139, 5.80832>
    <7.14387, 5.68128>
    <7.16466, 5.5539>
    <7.18354, 5.42616>
    <7.20091, 5.29816>
    <7.21669, 5.16992>
    <7.23086, 5.04145>
    <7.24373, 4.91281>
    <7.25489, 4.78398>
    <7.26476, 4.65502>
    <7.27301, 4.52593>
    <7.28012, 4.39675>
    <7.28584, 4.26749>
    <7.29029, 4.13817>
    <7.29354, 4.00881>
    <7.2954, 3.87941>
    <7.29629, 3.75>
    <7.2954, 3.62059>
    <7.29354, 3.49119>
    <7.29029, 3.36183>
    <7.28584, 3.23251>
    <7.28012, 3.10325>
    <7.27301, 2.97407>
    <7.26476, 2.84498>
    <7.25489, 2.71602>
    <7.24373, 2.58719>
    <7.23086, 2.45855>
    <7.21669, 2.33008>
    <7.20091, 2.20184>
    <7.18354, 2.07384>
    <7.16466, 1.9461>
    <7.14387, 1.81872>
    <7.12139, 1.69168>
    <7.09673, 1.56513>
    <7.07014, 1.43906>
    <7.04155, 1.31351>
    <7.01084, 1.18856>
    <6.97778, 1.06433>
    <6.94236, 0.940884>
    <6.90452, 0.818288>
    <6.86248, 0.697369>
    <6.81865, 0.577198>
    <6.7707, 0.45893>
    <6.71918, 0.342485>
    <6.66571, 0.227035>
    <6.59991, 0.119695>
    <6.51466, 0.0305235>
    <6.40148, 0>
    texture { Barrel } }
  matrix <1.00009, 0, 0.00305598, 0, 1, 0, 0.00305598, 0, 0.999917, -0.22823, 0, -0.460854>
}
plane { y, 0 texture { Fixture } }
