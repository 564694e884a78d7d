// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 78.564140, 0.000000>
  direction <0.000000, -1671.308131, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-16.020848, 75.397192, -13.500260> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <-7.124331, 75.397192, -19.701992> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <3.681145, 75.397192, -20.624591> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <13.500260, 75.397192, -16.020848> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <19.701992, 75.397192, -7.124331> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <20.624591, 75.397192, 3.681145> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <16.020848, 75.397192, 13.500260> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <7.124331, 75.397192, 19.701992> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <-3.681145, 75.397192, 20.624591> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <-13.500260, 75.397192, 16.020848> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <-19.701992, 75.397192, 7.124331> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
light_source { <-20.624591, 75.397192, -3.681145> rgb 0.166667 fade_distance 71.2055 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.044934 scale <0.559664, 0.0307025, 0.0307025> rotate y * 36.489 translate <44.719132, -29.413183, 38.789889> }
  finish { ambient 0 emission 0 diffuse 0.547074 specular 0.226677 roughness 0.0465624 metallic reflection { 0.0267242 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 1.23159 scallop_wave scale 0.0524414 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.0629618 specular 0.404095 roughness 0.0148251 metallic reflection { 0.464084 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.391319 sine_wave scale 0.0304427 translate <44.719132, -29.413183, 38.789889> }
  finish { ambient 0 emission 0 diffuse 0.610367 specular 0.194529 roughness 0.0791933 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.318248, 0.268282, 0.169948> }
  finish { ambient 0 emission 0 diffuse 0.508236 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.914134 FaceClean] [0.934134 Stain] [1 Stain] }
  scale 0.382492 translate <76.022524, -50.002412, 65.942811> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.914134 RingClean] [0.934134 Stain] [1 Stain] }
  scale 0.382492 translate <76.022524, -50.002412, 65.942811> }
#declare Fixture = texture {
  pigment { rgb <0.557544, 0.557544, 0.568479> }
  normal { bumps 0.323011 scale 0.287308 translate <44.719132, -29.413183, 38.789889> }
  finish { ambient 0 emission 0 diffuse 0.682051 specular 0.0975992 roughness 0.0501015 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.11083 * (1 + 0.0102759 * cos(2 * atan2(z, x) + 5.59539) + 0.0047314 * cos(3 * atan2(z, x) + 2.36801)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.52308
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.52308, 7.5>
    <6.6216, 7.43575>
    <6.69439, 7.33563>
    <6.74574, 7.2218>
    <6.78787, 7.10368>
    <6.82637, 6.98456>
    <6.86359, 6.86475>
    <6.89876, 6.74422>
    <6.93189, 6.62305>
    <6.96304, 6.50124>
    <6.99217, 6.37889>
    <7.0197, 6.25611>
    <7.04544, 6.13288>
    <7.0696, 6.00929>
    <7.09212, 5.88535>
    <7.11321, 5.76112>
    <7.13267, 5.63659>
    <7.15089, 5.51184>
    <7.16749, 5.38682>
    <7.18277, 5.26162>
    <7.19677, 5.13624>
    <7.20933, 5.01068>
    <7.22084, 4.88501>
    <7.23074, 4.75918>
    <7.2397, 4.63327>
    <7.24715, 4.50724>
    <7.25358, 4.38115>
    <7.25875, 4.25499>
    <7.26278, 4.12879>
    <7.26574, 4.00255>
    <7.26741, 3.87628>
    <7.26826, 3.75>
    <7.26741, 3.62372>
    <7.26574, 3.49745>
    <7.26278, 3.37121>
    <7.25875, 3.24501>
    <7.25358, 3.11885>
    <7.24715, 2.99276>
    <7.2397, 2.86673>
    <7.23074, 2.74082>
    <7.22084, 2.61499>
    <7.20933, 2.48932>
    <7.19677, 2.36376>
    <7.18277, 2.23838>
    <7.16749, 2.11318>
    <7.15089, 1.98816>
    <7.13267, 1.86341>
    <7.11321, 1.73888>
    <7.09212, 1.61465>
    <7.0696, 1.49071>
    <7.04544, 1.36712>
    <7.0197, 1.24389>
    <6.99217, 1.12111>
    <6.96304, 0.99876>
    <6.93189, 0.876949>
    <6.89876, 0.755782>
    <6.86359, 0.635254>
    <6.82637, 0.515435>
    <6.78787, 0.39632>
    <6.74574, 0.2782>
    <6.69439, 0.164371>
    <6.6216, 0.0642465>
    <6.52308, 0>
    texture { Barrel } }
  matrix <0.99593, 0, -0.00332552, 0, 1, 0, -0.00332552, 0, 1.0041, 4.2994, 0, 1.27604>
}
plane { y, 0 texture { Fixture } }
