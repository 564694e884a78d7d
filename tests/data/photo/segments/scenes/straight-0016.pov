// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 68.780377, 0.000000>
  direction <0.000000, -1682.256508, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-5.817078, 67.843322, 14.740565> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-8.665256, 67.843322, 13.267855> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-11.158678, 67.843322, 11.251958> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-13.195261, 67.843322, 8.775405> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-14.691630, 67.843322, 5.939585> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-15.586521, 67.843322, 2.860598> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-15.843298, 67.843322, -0.335502> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-15.451449, 67.843322, -3.517867> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-14.427015, 67.843322, -6.556209> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-12.811938, 67.843322, -9.326140> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-10.672339, 67.843322, -11.714258> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-8.095813, 67.843322, -13.622792> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-5.187843, 67.843322, -14.973608> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-2.067482, 67.843322, -15.711402> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <1.137521, 67.843322, -15.805970> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <4.295954, 67.843322, -15.253440> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <7.278511, 67.843322, -14.076432> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <9.963084, 67.843322, -12.323133> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <12.239768, 67.843322, -10.065323> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <14.015354, 67.843322, -7.395439> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <15.217149, 67.843322, -4.422784> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <15.795953, 67.843322, -1.269059> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <15.728069, 67.843322, 1.936620> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <15.016276, 67.843322, 5.063015> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <13.689714, 67.843322, 7.982129> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <11.802694, 67.843322, 10.574453> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <9.432471, 67.843322, 12.733858> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <6.676081, 67.843322, 14.371938> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <3.646371, 67.843322, 15.421629> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <0.467379, 67.843322, 15.839956> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
light_source { <-2.730748, 67.843322, 15.609794> rgb 0.0645161 fade_distance 61.3017 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.0469475 scale <0.446993, 0.0264389, 0.0264389> rotate y * 49.4239 translate <-31.113858, 27.765534, 11.766441> }
  finish { ambient 0 emission 0 diffuse 0.903958 specular 0.361028 roughness 0.0643519 metallic reflection { 0.06217 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 0.796168 scallop_wave scale 0.176005 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.395981 specular 0.138361 roughness 0.0588001 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.334406 sine_wave scale 0.108441 translate <-31.113858, 27.765534, 11.766441> }
  finish { ambient 0 emission 0 diffuse 0.355458 specular 0.108742 roughness 0.0679125 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.645660, 0.645660, 0.655798> }
  normal { bumps 0.183656 scale 0.188703 translate <-31.113858, 27.765534, 11.766441> }
  finish { ambient 0 emission 0 diffuse 0.886797 specular 0.0608016 roughness 0.11057 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.31071 * (1 + 0.0102048 * cos(2 * atan2(z, x) + 2.28071) + 0.00465258 * cos(3 * atan2(z, x) + 2.83936)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.27248
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.27248, 7.5>
    <6.37237, 7.4215>
    <6.44679, 7.31758>
    <6.51415, 7.20801>
    <6.57754, 7.09597>
    <6.63737, 6.98191>
    <6.69572, 6.8671>
    <6.75067, 6.75062>
    <6.80326, 6.63306>
    <6.85382, 6.51461>
    <6.90222, 6.39526>
    <6.94813, 6.27492>
    <6.99154, 6.15365>
    <7.03277, 6.03163>
    <7.07173, 5.90887>
    <7.10845, 5.7854>
    <7.14314, 5.66135>
    <7.17487, 5.5365>
    <7.20464, 5.41117>
    <7.23225, 5.28535>
    <7.25756, 5.15903>
    <7.2809, 5.03233>
    <7.30134, 4.90513>
    <7.31986, 4.77763>
    <7.33625, 4.64984>
    <7.35043, 4.52178>
    <7.36274, 4.39352>
    <7.37211, 4.26501>
    <7.37966, 4.13639>
    <7.38503, 4.00765>
    <7.38832, 3.87885>
    <7.38987, 3.75>
    <7.38832, 3.62115>
    <7.38503, 3.49235>
    <7.37966, 3.36361>
    <7.37211, 3.23499>
    <7.36274, 3.10648>
    <7.35043, 2.97822>
    <7.33625, 2.85016>
    <7.31986, 2.72237>
    <7.30134, 2.59487>
    <7.2809, 2.46767>
    <7.25756, 2.34097>
    <7.23225, 2.21465>
    <7.20464, 2.08883>
    <7.17487, 1.9635>
    <7.14314, 1.83865>
    <7.10845, 1.7146>
    <7.07173, 1.59113>
    <7.03277, 1.46837>
    <6.99154, 1.34635>
    <6.94813, 1.22508>
    <6.90222, 1.10474>
    <6.85382, 0.985385>
    <6.80326, 0.86694>
    <6.75067, 0.749383>
    <6.69572, 0.632895>
    <6.63737, 0.518089>
    <6.57754, 0.404032>
    <6.51415, 0.291989>
    <6.44679, 0.182416>
    <6.37237, 0.0785044>
    <6.27248, 0>
    texture { Barrel } }
  matrix <0.995151, 0, 0.00269443, 0, 1, 0, 0.00269443, 0, 1.00488, -1.61101, 0, -0.132718>
}
plane { y, 0 texture { Fixture } }
