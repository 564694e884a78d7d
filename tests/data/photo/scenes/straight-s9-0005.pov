// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 56.727115, 0.000000>
  direction <0.000000, -1240.688209, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <20.161911, 50.411703, -20.136056> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <25.607650, 50.411703, -12.498468> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <28.278402, 50.411703, -3.506476> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <27.884751, 50.411703, 5.865497> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <24.469355, 50.411703, 14.601852> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <18.402324, 50.411703, 21.755870> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <10.341116, 50.411703, 26.552302> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <1.159287, 50.411703, 28.471380> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <-8.148168, 50.411703, 27.305142> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <-16.572643, 50.411703, 23.179968> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <-23.201215, 50.411703, 16.542885> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <-27.315575, 50.411703, 8.113124> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <-28.469869, 50.411703, -1.195820> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <-26.539011, 50.411703, -10.375178> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <-21.732239, 50.411703, -18.430225> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <-14.570442, 50.411703, -24.488071> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <-5.829711, 50.411703, -27.892255> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <3.542759, 50.411703, -28.273880> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
light_source { <12.531316, 50.411703, -25.591591> rgb 0.105263 fade_distance 49.2495 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { bumps 0.0333389 scale <0.660506, 0.0361366, 0.0361366> rotate y * 54.1427 translate <-25.526030, 10.031318, 37.756231> }
  finish { ambient 0 emission 0 diffuse 0.5893 specular 0.235492 roughness 0.0561761 metallic }
}
#declare RingClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { onion 0.497675 scallop_wave scale 0.180757 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.592153 specular 0.101719 roughness 0.0777785 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { gradient y 0.367295 sine_wave scale 0.0996698 translate <-25.526030, 10.031318, 37.756231> }
  finish { ambient 0 emission 0 diffuse 0.530393 specular 0.12241 roughness 0.0687191 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.298536, 0.260179, 0.193456> }
  finish { ambient 0 emission 0 diffuse 0.63884 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.901767 FaceClean] [0.921767 Stain] [1 Stain] }
  scale 0.731332 translate <-43.394251, 17.053241, 64.185592> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.901767 RingClean] [0.921767 Stain] [1 Stain] }
  scale 0.731332 translate <-43.394251, 17.053241, 64.185592> }
#declare Fixture = texture {
  pigment { rgb <0.541746, 0.541746, 0.538315> }
  normal { bumps 0.358071 scale 0.276192 translate <-25.526030, 10.031318, 37.756231> }
  finish { ambient 0 emission 0 diffuse 0.720275 specular 0.0630064 roughness 0.103854 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.1583 * (1 + 0.00461221 * cos(2 * atan2(z, x) + 5.2583) + 0.00142841 * cos(3 * atan2(z, x) + 4.57523)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.53324
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.53324, 7.5>
    <6.63425, 7.44849>
    <6.70943, 7.35121>
    <6.76063, 7.23721>
    <6.80454, 7.11998>
    <6.84243, 7.00019>
    <6.88035, 6.88058>
    <6.91421, 6.75929>
    <6.94616, 6.63749>
    <6.97593, 6.51499>
    <7.00316, 6.39181>
    <7.02885, 6.26823>
    <7.05261, 6.1442>
    <7.07473, 6.01981>
    <7.09514, 5.89507>
    <7.11409, 5.77005>
    <7.13144, 5.64476>
    <7.14751, 5.51927>
    <7.16224, 5.39358>
    <7.1756, 5.26771>
    <7.18793, 5.14171>
    <7.19878, 5.01555>
    <7.20878, 4.8893>
    <7.21723, 4.76293>
    <7.22488, 4.63648>
    <7.23129, 4.50996>
    <7.23678, 4.38339>
    <7.24123, 4.25677>
    <7.24464, 4.13011>
    <7.24719, 4.00342>
    <7.24858, 3.87671>
    <7.24932, 3.75>
    <7.24858, 3.62329>
    <7.24719, 3.49658>
    <7.24464, 3.36989>
    <7.24123, 3.24323>
    <7.23678, 3.11661>
    <7.23129, 2.99004>
    <7.22488, 2.86352>
    <7.21723, 2.73707>
    <7.20878, 2.6107>
    <7.19878, 2.48445>
    <7.18793, 2.35829>
    <7.1756, 2.23229>
    <7.16224, 2.10642>
    <7.14751, 1.98073>
    <7.13144, 1.85524>
    <7.11409, 1.72995>
    <7.09514, 1.60493>
    <7.07473, 1.48019>
    <7.05261, 1.3558>
    <7.02885, 1.23177>
    <7.00316, 1.10819>
    <6.97593, 0.985006>
    <6.94616, 0.862508>
    <6.91421, 0.740712>
    <6.88035, 0.61942>
    <6.84243, 0.499809>
    <6.80454, 0.380024>
    <6.76063, 0.262787>
    <6.70943, 0.148788>
    <6.63425, 0.0515074>
    <6.53324, 0>
    texture { Barrel } }
  matrix <1.00231, 0, -0.00236437, 0, 1, 0, -0.00236437, 0, 0.997699, 1.43296, 0, -0.387694>
}
plane { y, 0 texture { Fixture } }
