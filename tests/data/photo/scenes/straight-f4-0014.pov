// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 70.361265, 0.000000>
  direction <0.000000, -1383.878149, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <28.833212, 66.992491, -9.008040> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <30.194338, 66.992491, -0.894890> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <29.316089, 66.992491, 7.284630> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <26.263599, 66.992491, 14.923882> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <21.263258, 66.992491, 21.456298> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <14.685919, 66.992491, 26.397399> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <7.019392, 66.992491, 29.380725> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-1.167731, 66.992491, 30.185018> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-9.268248, 66.992491, 28.750625> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-16.681383, 66.992491, 25.183931> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-22.857335, 66.992491, 19.749459> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-27.338063, 66.992491, 12.850260> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-29.791252, 66.992491, 4.998017> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-30.034961, 66.992491, -3.224907> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-28.051113, 66.992491, -11.208654> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-23.986843, 66.992491, -18.361107> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-18.143579, 66.992491, -24.151800> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-10.954688, 66.992491, -28.151265> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <-2.953338, 66.992491, -30.062879> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <5.267047, 66.992491, -29.744867> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <13.096800, 66.992491, -27.220814> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <19.955223, 66.992491, -22.677918> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
light_source { <25.333658, 66.992491, -16.453105> rgb 0.0869565 fade_distance 63.1146 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.0478347 scale <0.27192, 0.0200163, 0.0200163> rotate y * 5.85114 translate <29.473108, 36.689001, -40.472578> }
  finish { ambient 0 emission 0 diffuse 0.857427 specular 0.352237 roughness 0.0404993 metallic reflection { 0.0919618 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 1.03906 scallop_wave scale 0.158289 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.394685 specular 0.100395 roughness 0.0979655 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.307241 sine_wave scale 0.07819 translate <29.473108, 36.689001, -40.472578> }
  finish { ambient 0 emission 0 diffuse 0.297473 specular 0.0866898 roughness 0.0714688 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.379308, 0.310749, 0.197506> }
  finish { ambient 0 emission 0 diffuse 0.303768 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.886458 FaceClean] [0.906458 Stain] [1 Stain] }
  scale 1.1699 translate <50.104283, 62.371302, -68.803383> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.886458 RingClean] [0.906458 Stain] [1 Stain] }
  scale 1.1699 translate <50.104283, 62.371302, -68.803383> }
#declare Fixture = texture {
  pigment { rgb <0.053517, 0.053517, 0.051967> }
  normal { bumps 0.38464 scale 0.0772058 translate <29.473108, 36.689001, -40.472578> }
  finish { ambient 0 emission 0 diffuse 0.64012 specular 0.0853891 roughness 0.0537391 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.56305 * (1 + 0.00589711 * cos(2 * atan2(z, x) + 4.81866) + 0.00518087 * cos(3 * atan2(z, x) + 3.37635)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.34321
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.34321, 7.5>
    <6.45896, 7.49151>
    <6.54777, 7.46963>
    <6.61761, 7.44221>
    <6.67708, 7.41221>
    <6.73397, 7.381>
    <6.78615, 7.34825>
    <6.83479, 7.31406>
    <6.88058, 7.27847>
    <6.92264, 7.24128>
    <6.96211, 7.20255>
    <6.99922, 7.16218>
    <7.03312, 7.11996>
    <7.06495, 7.07587>
    <7.09449, 7.02971>
    <7.12188, 6.98129>
    <7.14713, 6.93038>
    <7.17043, 6.87671>
    <7.19152, 6.81992>
    <7.21087, 6.75964>
    <7.22843, 6.69535>
    <7.24429, 6.62641>
    <7.25859, 6.55199>
    <7.27115, 6.47099>
    <7.28226, 6.38191>
    <7.29148, 6.2826>
    <7.29941, 6.16991>
    <7.30578, 6.03873>
    <7.31076, 5.87999>
    <7.31437, 5.67473>
    <7.31649, 5.36852>
    <7.31746, 3.75>
    <7.31649, 2.13148>
    <7.31437, 1.82527>
    <7.31076, 1.62001>
    <7.30578, 1.46127>
    <7.29941, 1.33009>
    <7.29148, 1.2174>
    <7.28226, 1.11809>
    <7.27115, 1.02901>
    <7.25859, 0.948006>
    <7.24429, 0.873589>
    <7.22843, 0.804648>
    <7.21087, 0.740358>
    <7.19152, 0.680078>
    <7.17043, 0.623291>
    <7.14713, 0.569624>
    <7.12188, 0.518713>
    <7.09449, 0.470292>
    <7.06495, 0.42413>
    <7.03312, 0.380036>
    <6.99922, 0.337816>
    <6.96211, 0.297453>
    <6.92264, 0.258718>
    <6.88058, 0.221534>
    <6.83479, 0.185942>
    <6.78615, 0.151752>
    <6.73397, 0.118997>
    <6.67708, 0.0877914>
    <6.61761, 0.0577877>
    <6.54777, 0.0303742>
    <6.45896, 0.0084854>
    <6.34321, 0>
    texture { Barrel } }
  matrix <0.999751, 0, -0.00118429, 0, 1, 0, -0.00118429, 0, 1.00025, -5.4021, 0, -1.65308>
}
plane { y, 0 texture { Fixture } }
