// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 92.775739, 0.000000>
  direction <0.000000, -2267.473538, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-19.507654, 89.267222, 8.804981> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-21.159812, 89.267222, 3.215366> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-21.242645, 89.267222, -2.612717> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-19.750007, 89.267222, -8.247028> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-16.792602, 89.267222, -13.269694> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-12.589766, 89.267222, -17.308207> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-7.453205, 89.267222, -20.063050> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-1.763874, 89.267222, -21.329908> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <4.056276, 89.267222, -21.014825> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <9.575590, 89.267222, -19.141168> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <14.384727, 89.267222, -15.847899> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <18.127014, 89.267222, -11.379263> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <20.524903, 89.267222, -6.066679> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <21.400555, 89.267222, -0.304157> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <20.689025, 89.267222, 5.480922> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <18.443084, 89.267222, 10.859507> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <14.829305, 89.267222, 15.432691> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <10.115704, 89.267222, 18.861304> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <4.651867, 89.267222, 20.891060> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-1.156977, 89.267222, 21.371421> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-6.880014, 89.267222, 20.266762> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-12.092791, 89.267222, 17.659010> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
light_source { <-16.408702, 89.267222, 13.741570> rgb 0.0869565 fade_distance 85.2772 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { bumps 0.05581 scale <0.512524, 0.0264552, 0.0264552> rotate y * 102.813 translate <-44.882607, 18.987931, 38.423343> }
  finish { ambient 0 emission 0 diffuse 0.757928 specular 0.241299 roughness 0.0498051 metallic reflection { 0.0069408 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { onion 0.341685 scallop_wave scale 0.0929596 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.293535 specular 0.110281 roughness 0.06801 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { gradient y 0.367719 sine_wave scale 0.0568263 translate <-44.882607, 18.987931, 38.423343> }
  finish { ambient 0 emission 0 diffuse 0.370078 specular 0.177796 roughness 0.0508828 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.472015, 0.472015, 0.475463> }
  normal { bumps 0.144858 scale 0.0762701 translate <-44.882607, 18.987931, 38.423343> }
  finish { ambient 0 emission 0 diffuse 0.687811 specular 0.0896029 roughness 0.0642856 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.48339 * (1 + 0.00774324 * cos(2 * atan2(z, x) + 4.70763) + 0.00112702 * cos(3 * atan2(z, x) + 3.88528)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.32247
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.32247, 7.5>
    <6.43525, 7.48903>
    <6.52194, 7.46632>
    <6.59143, 7.43861>
    <6.65263, 7.40869>
    <6.71064, 7.37747>
    <6.76453, 7.34479>
    <6.81514, 7.31071>
    <6.86264, 7.2752>
    <6.90699, 7.23816>
    <6.94877, 7.19958>
    <6.98801, 7.15934>
    <7.02429, 7.11728>
    <7.0584, 7.07333>
    <7.0902, 7.02732>
    <7.11971, 6.97903>
    <7.14706, 6.92826>
    <7.17235, 6.87472>
    <7.19542, 6.81806>
    <7.21665, 6.7579>
    <7.23589, 6.69372>
    <7.2533, 6.62488>
    <7.26895, 6.55055>
    <7.2828, 6.46964>
    <7.2951, 6.38065>
    <7.30537, 6.28143>
    <7.31418, 6.16882>
    <7.32118, 6.03772>
    <7.32671, 5.87907>
    <7.3307, 5.6739>
    <7.33305, 5.36783>
    <7.33415, 3.75>
    <7.33305, 2.13217>
    <7.3307, 1.8261>
    <7.32671, 1.62093>
    <7.32118, 1.46228>
    <7.31418, 1.33118>
    <7.30537, 1.21857>
    <7.2951, 1.11935>
    <7.2828, 1.03036>
    <7.26895, 0.949447>
    <7.2533, 0.875121>
    <7.23589, 0.806282>
    <7.21665, 0.7421>
    <7.19542, 0.681944>
    <7.17235, 0.625284>
    <7.14706, 0.571744>
    <7.11971, 0.520968>
    <7.0902, 0.472681>
    <7.0584, 0.426666>
    <7.02429, 0.382721>
    <6.98801, 0.340658>
    <6.94877, 0.300424>
    <6.90699, 0.261841>
    <6.86264, 0.224805>
    <6.81514, 0.18929>
    <6.76453, 0.155214>
    <6.71064, 0.122531>
    <6.65263, 0.0913128>
    <6.59143, 0.0613857>
    <6.52194, 0.033677>
    <6.43525, 0.0109701>
    <6.32247, 0>
    texture { Barrel } }
  matrix <1.00079, 0, -2.02144e-05, 0, 1, 0, -2.02144e-05, 0, 0.999215, 0.492072, 0, -0.0154797>
}
plane { y, 0 texture { Fixture } }
