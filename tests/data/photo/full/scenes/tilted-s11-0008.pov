// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <-9.536337, 73.595777, -4.210277>
  direction <548.286798, -3789.434371, 175.212827>
  right <1441.018294, 208.277114, -4.787617>
  up <-3.577560, 49.735579, 1086.856740> }
light_source { <-32.933678, 69.555042, -2.591265> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-32.221025, 69.315795, -9.995689> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-29.277727, 69.425630, -16.830567> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-24.391895, 69.873796, -22.426852> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-18.041787, 70.616424, -26.236741> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-10.848997, 71.580820, -27.887295> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-3.517605, 72.672581, -27.216948> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <3.234741, 73.784840, -24.291316> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <8.747075, 74.808719, -19.396782> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <12.479811, 75.643996, -13.012456> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <14.067562, 76.208906, -5.763281> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <13.354909, 76.448154, 1.641144> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <10.411611, 76.338318, 8.476021> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <5.525778, 75.890152, 14.072306> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-0.824330, 75.147525, 17.882195> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-8.017120, 74.183129, 19.532750> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-15.348512, 73.091367, 18.862402> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-22.100858, 71.979109, 15.936770> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-27.613192, 70.955229, 11.042236> rgb 0.1 fade_distance 66.9128 fade_power 2 }
light_source { <-31.345927, 70.119953, 4.657910> rgb 0.1 fade_distance 66.9128 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.100264 scale <0.479602, 0.0243772, 0.0243772> rotate y * 84.6385 translate <-18.130574, -24.238445, -10.447912> }
  finish { ambient 0 emission 0 diffuse 0.449812 specular 0.343324 roughness 0.0586651 metallic reflection { 0.0762434 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 0.902311 scallop_wave scale 0.0979267 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.0506532 specular 0.678213 roughness 0.00792105 metallic reflection { 0.443811 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.243792 sine_wave scale 0.0544505 translate <-18.130574, -24.238445, -10.447912> }
  finish { ambient 0 emission 0 diffuse 0.663868 specular 0.137403 roughness 0.0765936 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.289990, 0.267270, 0.229935> }
  finish { ambient 0 emission 0 diffuse 0.492354 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.912784 FaceClean] [0.932784 Stain] [1 Stain] }
  scale 0.676735 translate <-30.821976, -41.205356, -17.761450> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.912784 RingClean] [0.932784 Stain] [1 Stain] }
  scale 0.676735 translate <-30.821976, -41.205356, -17.761450> }
#declare Fixture = texture {
  pigment { rgb <0.743825, 0.743825, 0.757731> }
  normal { bumps 0.235267 scale 0.13579 translate <-18.130574, -24.238445, -10.447912> }
  finish { ambient 0 emission 0 diffuse 0.866684 specular 0.139337 roughness 0.0661627 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.44441 * (1 + 0.00142249 * cos(2 * atan2(z, x) + 3.67498) + 0.000482832 * cos(3 * atan2(z, x) + 5.6714)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.30962
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.30962, 7.5>
    <6.42387, 7.45376>
    <6.51381, 7.36794>
    <6.58639, 7.26319>
    <6.65131, 7.1524>
    <6.71248, 7.03929>
    <6.76775, 6.92286>
    <6.81958, 6.80471>
    <6.86776, 6.68492>
    <6.91244, 6.56364>
    <6.95408, 6.44116>
    <6.99325, 6.31779>
    <7.02848, 6.19314>
    <7.06173, 6.06789>
    <7.09244, 5.94194>
    <7.12073, 5.81535>
    <7.14701, 5.6883>
    <7.17098, 5.56074>
    <7.19274, 5.43275>
    <7.21258, 5.30442>
    <7.23057, 5.17579>
    <7.24681, 5.04691>
    <7.26136, 4.9178>
    <7.27424, 4.7885>
    <7.28551, 4.65903>
    <7.29497, 4.5294>
    <7.30299, 4.39966>
    <7.30947, 4.26984>
    <7.31453, 4.13994>
    <7.31817, 4.00999>
    <7.32036, 3.88>
    <7.32128, 3.75>
    <7.32036, 3.62>
    <7.31817, 3.49001>
    <7.31453, 3.36006>
    <7.30947, 3.23016>
    <7.30299, 3.10034>
    <7.29497, 2.9706>
    <7.28551, 2.84097>
    <7.27424, 2.7115>
    <7.26136, 2.5822>
    <7.24681, 2.45309>
    <7.23057, 2.32421>
    <7.21258, 2.19558>
    <7.19274, 2.06725>
    <7.17098, 1.93926>
    <7.14701, 1.8117>
    <7.12073, 1.68465>
    <7.09244, 1.55806>
    <7.06173, 1.43211>
    <7.02848, 1.30686>
    <6.99325, 1.18221>
    <6.95408, 1.05884>
    <6.91244, 0.936361>
    <6.86776, 0.815081>
    <6.81958, 0.695289>
    <6.76775, 0.577145>
    <6.71248, 0.460714>
    <6.65131, 0.3476>
    <6.58639, 0.236807>
    <6.51381, 0.132065>
    <6.42387, 0.0462367>
    <6.30962, 0>
    texture { Barrel } }
  matrix <0.997287, 0, -0.00170923, 0, 1, 0, -0.00170923, 0, 1.00272, 0, 0, 0>
}
plane { y, 0 texture { Fixture } }
