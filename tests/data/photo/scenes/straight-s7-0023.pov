// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 68.353828, 0.000000>
  direction <0.000000, -1342.539016, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <16.442234, 67.364724, 18.838014> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <12.008207, 67.364724, 21.932186> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <7.012690, 67.364724, 24.000834> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <1.689268, 67.364724, 24.947229> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-3.713143, 67.364724, 24.727119> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-8.941932, 67.364724, 23.350797> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-13.752605, 67.364724, 20.882617> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-17.920222, 67.364724, 17.437989> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-21.249910, 67.364724, 13.177981> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-23.585975, 67.364724, 8.301785> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-24.819186, 67.364724, 3.037406> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-24.891880, 67.364724, -2.368998> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-23.800657, 67.364724, -7.664631> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-21.596542, 67.364724, -12.601874> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-18.382596, 67.364724, -16.949867> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-14.309101, 67.364724, -20.505303> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-9.566528, 67.364724, -23.101935> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <-4.376635, 67.364724, -24.618345> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <1.017905, 67.364724, -24.983629> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <6.364848, 67.364724, -24.180706> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <11.414179, 67.364724, -22.247120> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <15.929795, 67.364724, -19.273284> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <19.700551, 67.364724, -15.398250> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <22.550132, 67.364724, -10.803212> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <24.345294, 67.364724, -5.703027> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <25.002096, 67.364724, -0.336175> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <24.489829, 67.364724, 5.046397> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <22.832444, 67.364724, 10.193004> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
light_source { <20.107440, 67.364724, 14.862998> rgb 0.0689655 fade_distance 61.0357 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { bumps 0.0412786 scale <0.444521, 0.0235081, 0.0235081> rotate y * 127.353 translate <-11.880900, -5.094079, 24.078179> }
  finish { ambient 0 emission 0 diffuse 0.385557 specular 0.118998 roughness 0.0431158 metallic reflection { 0.060182 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { onion 1.00601 scallop_wave scale 0.0938114 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.088505 specular 0.455476 roughness 0.00645666 metallic reflection { 0.435636 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { gradient y 0.221841 sine_wave scale 0.0449219 translate <-11.880900, -5.094079, 24.078179> }
  finish { ambient 0 emission 0 diffuse 0.876789 specular 0.17329 roughness 0.0707444 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.267049, 0.315004, 0.202660> }
  finish { ambient 0 emission 0 diffuse 0.547226 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.882819 FaceClean] [0.902819 Stain] [1 Stain] }
  scale 0.837254 translate <-20.197530, -8.659934, 40.932905> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.882819 RingClean] [0.902819 Stain] [1 Stain] }
  scale 0.837254 translate <-20.197530, -8.659934, 40.932905> }
#declare Fixture = texture {
  pigment { rgb <0.787866, 0.787866, 0.801609> }
  normal { bumps 0.295818 scale 0.191267 translate <-11.880900, -5.094079, 24.078179> }
  finish { ambient 0 emission 0 diffuse 0.644258 specular 0.0856092 roughness 0.157617 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.62267 * (1 + 0.00413814 * cos(2 * atan2(z, x) + 2.12473) + 0.00228494 * cos(3 * atan2(z, x) + 1.01892)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.35522
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.35522, 7.5>
    <6.46768, 7.44802>
    <6.55303, 7.35616>
    <6.62243, 7.24972>
    <6.68278, 7.13724>
    <6.74032, 7.02316>
    <6.79227, 6.90621>
    <6.84055, 6.78756>
    <6.88577, 6.66761>
    <6.92706, 6.54614>
    <6.96549, 6.42366>
    <7.00157, 6.30041>
    <7.03421, 6.17611>
    <7.06482, 6.05125>
    <7.09315, 5.92581>
    <7.11928, 5.79984>
    <7.14331, 5.67342>
    <7.16536, 5.54661>
    <7.18529, 5.41941>
    <7.20352, 5.29194>
    <7.22005, 5.16422>
    <7.23494, 5.03627>
    <7.24834, 4.90814>
    <7.26009, 4.77984>
    <7.27043, 4.6514>
    <7.27905, 4.52282>
    <7.28642, 4.39416>
    <7.29236, 4.26541>
    <7.297, 4.13661>
    <7.30036, 4.00777>
    <7.30233, 3.87889>
    <7.30322, 3.75>
    <7.30233, 3.62111>
    <7.30036, 3.49223>
    <7.297, 3.36339>
    <7.29236, 3.23459>
    <7.28642, 3.10584>
    <7.27905, 2.97718>
    <7.27043, 2.8486>
    <7.26009, 2.72016>
    <7.24834, 2.59186>
    <7.23494, 2.46373>
    <7.22005, 2.33578>
    <7.20352, 2.20806>
    <7.18529, 2.08059>
    <7.16536, 1.95339>
    <7.14331, 1.82658>
    <7.11928, 1.70016>
    <7.09315, 1.57419>
    <7.06482, 1.44875>
    <7.03421, 1.32389>
    <7.00157, 1.19959>
    <6.96549, 1.07634>
    <6.92706, 0.953858>
    <6.88577, 0.832394>
    <6.84055, 0.712442>
    <6.79227, 0.593792>
    <6.74032, 0.476843>
    <6.68278, 0.362757>
    <6.62243, 0.250282>
    <6.55303, 0.143836>
    <6.46768, 0.0519772>
    <6.35522, 0>
    texture { Barrel } }
  matrix <0.997228, 0, 0.00549872, 0, 1, 0, 0.00549872, 0, 1.00281, -4.49949, 0, -1.38494>
}
plane { y, 0 texture { Fixture } }
