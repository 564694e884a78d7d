// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 64.249400, 0.000000>
  direction <0.000000, -1438.010602, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-28.234438, 59.413357, 17.750271> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-31.390117, 59.413357, 11.265710> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-33.078028, 59.413357, 4.254377> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-33.219247, 59.413357, -2.955886> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-31.807171, 59.413357, -10.027936> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-28.907828, 59.413357, -16.631090> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-24.656786, 59.413357, -22.456592> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-19.252820, 59.413357, -27.232050> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-12.948614, 59.413357, -30.734167> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-6.038946, 59.413357, -32.799189> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <1.153098, 59.413357, -33.330557> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <8.291223, 59.413357, -32.303425> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <15.041660, 59.413357, -29.765821> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <21.088766, 59.413357, -25.836400> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <26.149785, 59.413357, -20.698898> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <29.988069, 59.413357, -14.593538> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <32.424144, 59.413357, -7.805801> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <33.344102, 59.413357, -0.653074> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <32.704927, 59.413357, 6.530191> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <30.536506, 59.413357, 13.408112> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <26.940232, 59.413357, 19.659083> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <22.084262, 59.413357, 24.990818> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <16.195657, 59.413357, 29.154011> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <9.549761, 59.413357, 31.953994> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <2.457329, 59.413357, 33.259843> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-4.750005, 59.413357, 33.010500> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-11.735234, 59.413357, 31.217622> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-18.171737, 59.413357, 27.965043> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
light_source { <-23.758549, 59.413357, 23.404849> rgb 0.0689655 fade_distance 56.8169 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { bumps 0.0887424 scale <0.599122, 0.0349582, 0.0349582> rotate y * 145.633 translate <-5.273094, -9.298305, -23.526096> }
  finish { ambient 0 emission 0 diffuse 0.679022 specular 0.32225 roughness 0.0641359 metallic reflection { 0.0886643 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { onion 0.961168 scallop_wave scale 0.146858 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.427567 specular 0.125837 roughness 0.0998249 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { gradient y 0.235114 sine_wave scale 0.092605 translate <-5.273094, -9.298305, -23.526096> }
  finish { ambient 0 emission 0 diffuse 0.41433 specular 0.067689 roughness 0.090934 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.345863, 0.253056, 0.157656> }
  finish { ambient 0 emission 0 diffuse 0.307977 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.884932 FaceClean] [0.904932 Stain] [1 Stain] }
  scale 0.929018 translate <-8.964260, -15.807118, -39.994364> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.884932 RingClean] [0.904932 Stain] [1 Stain] }
  scale 0.929018 translate <-8.964260, -15.807118, -39.994364> }
#declare Fixture = texture {
  pigment { rgb <0.042408, 0.042408, 0.041428> }
  normal { bumps 0.383687 scale 0.0938568 translate <-5.273094, -9.298305, -23.526096> }
  finish { ambient 0 emission 0 diffuse 0.702903 specular 0.0732961 roughness 0.178039 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.0359 * (1 + 0.00838871 * cos(2 * atan2(z, x) + 1.42692) + 0.00400805 * cos(3 * atan2(z, x) + 4.13227)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.4877
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.4877, 7.5>
    <6.5986, 7.49195>
    <6.6761, 7.46785>
    <6.7301, 7.43842>
    <6.77844, 7.40746>
    <6.81988, 7.37479>
    <6.86257, 7.34138>
    <6.89885, 7.30626>
    <6.93415, 7.26996>
    <6.96646, 7.2322>
    <6.99629, 7.19291>
    <7.02436, 7.15207>
    <7.05042, 7.10952>
    <7.07468, 7.06513>
    <7.09702, 7.01871>
    <7.11774, 6.9701>
    <7.13668, 6.91904>
    <7.15429, 6.86528>
    <7.17037, 6.80848>
    <7.18502, 6.74822>
    <7.19847, 6.684>
    <7.2104, 6.61516>
    <7.22136, 6.54091>
    <7.23062, 6.46009>
    <7.23899, 6.37127>
    <7.246, 6.27229>
    <7.25202, 6.16>
    <7.25688, 6.02932>
    <7.26063, 5.87119>
    <7.26341, 5.66676>
    <7.26495, 5.36181>
    <7.26573, 3.75>
    <7.26495, 2.13819>
    <7.26341, 1.83324>
    <7.26063, 1.62881>
    <7.25688, 1.47068>
    <7.25202, 1.34>
    <7.246, 1.22771>
    <7.23899, 1.12873>
    <7.23062, 1.03991>
    <7.22136, 0.959094>
    <7.2104, 0.884838>
    <7.19847, 0.816>
    <7.18502, 0.751783>
    <7.17037, 0.69152>
    <7.15429, 0.634715>
    <7.13668, 0.580959>
    <7.11774, 0.529899>
    <7.09702, 0.481286>
    <7.07468, 0.434872>
    <7.05042, 0.390479>
    <7.02436, 0.347927>
    <6.99629, 0.307086>
    <6.96646, 0.267802>
    <6.93415, 0.230039>
    <6.89885, 0.19374>
    <6.86257, 0.15862>
    <6.81988, 0.125206>
    <6.77844, 0.0925428>
    <6.7301, 0.0615846>
    <6.6761, 0.032155>
    <6.5986, 0.00805222>
    <6.4877, 0>
    texture { Barrel } }
  matrix <1.00226, 0, 0.00294681, 0, 1, 0, 0.00294681, 0, 0.997758, -2.66427, 0, 0.749803>
}
plane { y, 0 texture { Fixture } }
