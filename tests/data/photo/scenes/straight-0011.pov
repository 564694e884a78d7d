// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 85.734698, 0.000000>
  direction <0.000000, -2097.370760, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <12.896890, 81.008627, 14.695275> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <8.837145, 81.008627, 17.440922> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <4.222129, 81.008627, 19.090692> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-0.658179, 81.008627, 19.540923> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-5.497131, 81.008627, 18.763327> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-9.990679, 81.008627, 16.806761> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-13.856475, 81.008627, 13.794165> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-16.851618, 81.008627, 9.914831> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-18.787911, 81.008627, 5.412512> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-19.543691, 81.008627, 0.570104> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-19.071469, 81.008627, -4.308125> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-17.400917, 81.008627, -8.915659> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-14.637001, 81.008627, -12.962989> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-10.953388, 81.008627, -16.195807> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-6.581534, 81.008627, -18.410983> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <-1.796138, 81.008627, -19.469329> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <3.102117, 81.008627, -19.304346> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <7.805453, 81.008627, -17.926399> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <12.018345, 81.008627, -15.422071> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <15.476080, 81.008627, -11.948717> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <17.961395, 81.008627, -7.724582> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <19.318130, 81.008627, -3.015083> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <19.461036, 81.008627, 1.883865> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <18.381134, 81.008627, 6.664443> rgb 0.08 fade_distance 78.2713 fade_power 2 }
light_source { <16.146277, 81.008627, 11.026270> rgb 0.08 fade_distance 78.2713 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { bumps 0.0591327 scale <0.195632, 0.0258867, 0.0258867> rotate y * 19.9657 translate <-1.055693, -28.894298, -25.780591> }
  finish { ambient 0 emission 0 diffuse 0.796548 specular 0.332585 roughness 0.0680128 metallic reflection { 0.061859 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { onion 0.47468 scallop_wave scale 0.0765003 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.30608 specular 0.105964 roughness 0.0799606 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { gradient y 0.213383 sine_wave scale 0.0357984 translate <-1.055693, -28.894298, -25.780591> }
  finish { ambient 0 emission 0 diffuse 0.395708 specular 0.135147 roughness 0.0796689 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.295790, 0.313225, 0.180678> }
  finish { ambient 0 emission 0 diffuse 0.588639 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.866222 FaceClean] [0.886222 Stain] [1 Stain] }
  scale 0.822029 translate <-1.794679, -49.120307, -43.827004> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.866222 RingClean] [0.886222 Stain] [1 Stain] }
  scale 0.822029 translate <-1.794679, -49.120307, -43.827004> }
#declare Fixture = texture {
  pigment { rgb <0.743358, 0.743358, 0.748714> }
  normal { bumps 0.353097 scale 0.124681 translate <-1.055693, -28.894298, -25.780591> }
  finish { ambient 0 emission 0 diffuse 0.813904 specular 0.0501302 roughness 0.125552 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.53635 * (1 + 0.00275803 * cos(2 * atan2(z, x) + 1.05475) + 0.00274343 * cos(3 * atan2(z, x) + 3.05965)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.3403
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.3403, 7.5>
    <6.4385, 7.42084>
    <6.5106, 7.3165>
    <6.57025, 7.204>
    <6.62716, 7.08993>
    <6.68201, 6.97474>
    <6.73452, 6.85851>
    <6.78501, 6.7413>
    <6.83273, 6.62294>
    <6.8786, 6.50384>
    <6.92244, 6.38397>
    <6.96411, 6.2633>
    <7.00355, 6.14187>
    <7.04095, 6.01978>
    <7.07633, 5.89707>
    <7.10945, 5.77372>
    <7.14072, 5.64988>
    <7.16958, 5.52542>
    <7.19646, 5.40052>
    <7.22144, 5.27521>
    <7.24422, 5.14947>
    <7.26514, 5.0234>
    <7.28366, 4.89694>
    <7.30036, 4.77021>
    <7.31519, 4.64325>
    <7.3279, 4.51605>
    <7.3389, 4.38868>
    <7.34737, 4.26111>
    <7.35417, 4.13344>
    <7.35903, 4.00568>
    <7.36198, 3.87785>
    <7.36337, 3.75>
    <7.36198, 3.62215>
    <7.35903, 3.49432>
    <7.35417, 3.36656>
    <7.34737, 3.23889>
    <7.3389, 3.11132>
    <7.3279, 2.98395>
    <7.31519, 2.85675>
    <7.30036, 2.72979>
    <7.28366, 2.60306>
    <7.26514, 2.4766>
    <7.24422, 2.35053>
    <7.22144, 2.22479>
    <7.19646, 2.09948>
    <7.16958, 1.97458>
    <7.14072, 1.85012>
    <7.10945, 1.72628>
    <7.07633, 1.60293>
    <7.04095, 1.48022>
    <7.00355, 1.35813>
    <6.96411, 1.2367>
    <6.92244, 1.11603>
    <6.8786, 0.996157>
    <6.83273, 0.877061>
    <6.78501, 0.758698>
    <6.73452, 0.641494>
    <6.68201, 0.525256>
    <6.62716, 0.410074>
    <6.57025, 0.296005>
    <6.5106, 0.183504>
    <6.4385, 0.0791628>
    <6.3403, 0>
    texture { Barrel } }
  matrix <1.00457, 0, -0.00446484, 0, 1, 0, -0.00446484, 0, 0.99547, -2.39323, 0, 0.0921858>
}
plane { y, 0 texture { Fixture } }
