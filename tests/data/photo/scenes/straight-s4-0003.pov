// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 79.053484, 0.000000>
  direction <0.000000, -1573.557399, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <18.974575, 73.520280, 23.989485> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <12.412512, 73.520280, 27.954596> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <5.070524, 73.520280, 30.163217> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-2.590063, 73.520280, 30.476572> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-10.087906, 73.520280, 28.874972> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-16.951890, 73.520280, 25.459052> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-22.750724, 73.520280, 20.443445> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-27.120046, 73.520280, 14.143302> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-29.785316, 73.520280, 6.954483> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-30.579065, 73.520280, -0.671312> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-29.451419, 73.520280, -8.254926> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-26.473232, 73.520280, -15.319852> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-21.831635, 73.520280, -21.422176> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-15.818275, 73.520280, -26.178466> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-8.810995, 73.520280, -29.289866> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <-1.250088, 73.520280, -30.560876> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <6.389367, 73.520280, -29.911635> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <13.627354, 73.520280, -27.382935> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <20.009084, 73.520280, -23.133664> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <25.133571, 73.520280, -17.430821> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <28.678822, 73.520280, -10.632735> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <30.422078, 73.520280, -3.166555> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <30.253802, 73.520280, 4.498592> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <28.184569, 73.520280, 11.881075> rgb 0.08 fade_distance 71.6173 fade_power 2 }
light_source { <24.344396, 73.520280, 18.517026> rgb 0.08 fade_distance 71.6173 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.0458113 scale <0.250375, 0.0330638, 0.0330638> rotate y * 0.650302 translate <22.746131, 31.482759, -22.702515> }
  finish { ambient 0 emission 0 diffuse 0.532006 specular 0.339044 roughness 0.0378424 metallic reflection { 0.00904908 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 0.450725 scallop_wave scale 0.104548 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.045427 specular 0.670643 roughness 0.00753676 metallic reflection { 0.498918 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.398004 sine_wave scale 0.0634258 translate <22.746131, 31.482759, -22.702515> }
  finish { ambient 0 emission 0 diffuse 0.767092 specular 0.29845 roughness 0.0781223 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.344641, 0.232180, 0.219702> }
  finish { ambient 0 emission 0 diffuse 0.372829 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.925207 FaceClean] [0.945207 Stain] [1 Stain] }
  scale 0.409294 translate <38.668423, 53.520690, -38.594276> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.925207 RingClean] [0.945207 Stain] [1 Stain] }
  scale 0.409294 translate <38.668423, 53.520690, -38.594276> }
#declare Fixture = texture {
  pigment { rgb <0.717325, 0.717325, 0.723723> }
  normal { bumps 0.211511 scale 0.0627069 translate <22.746131, 31.482759, -22.702515> }
  finish { ambient 0 emission 0 diffuse 0.621294 specular 0.144955 roughness 0.127135 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.25862 * (1 + 0.0032244 * cos(2 * atan2(z, x) + 1.94603) + 0.00503763 * cos(3 * atan2(z, x) + 3.56235)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.57482
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.57482, 7.5>
    <6.66677, 7.42982>
    <6.73792, 7.32987>
    <6.78569, 7.21524>
    <6.82476, 7.09682>
    <6.85865, 6.97674>
    <6.89201, 6.85644>
    <6.92351, 6.7355>
    <6.95269, 6.61394>
    <6.98039, 6.49195>
    <7.0058, 6.36942>
    <7.02986, 6.24656>
    <7.05222, 6.12334>
    <7.07313, 5.99983>
    <7.0925, 5.87603>
    <7.11061, 5.752>
    <7.12725, 5.62775>
    <7.14273, 5.50332>
    <7.15693, 5.3787>
    <7.16986, 5.25393>
    <7.18181, 5.12905>
    <7.19237, 5.00402>
    <7.2021, 4.87891>
    <7.21038, 4.75367>
    <7.21789, 4.62838>
    <7.22415, 4.50301>
    <7.22955, 4.37759>
    <7.23391, 4.25213>
    <7.23727, 4.12663>
    <7.23978, 4.0011>
    <7.24114, 3.87555>
    <7.24187, 3.75>
    <7.24114, 3.62445>
    <7.23978, 3.4989>
    <7.23727, 3.37337>
    <7.23391, 3.24787>
    <7.22955, 3.12241>
    <7.22415, 2.99699>
    <7.21789, 2.87162>
    <7.21038, 2.74633>
    <7.2021, 2.62109>
    <7.19237, 2.49598>
    <7.18181, 2.37095>
    <7.16986, 2.24607>
    <7.15693, 2.1213>
    <7.14273, 1.99668>
    <7.12725, 1.87225>
    <7.11061, 1.748>
    <7.0925, 1.62397>
    <7.07313, 1.50017>
    <7.05222, 1.37666>
    <7.02986, 1.25344>
    <7.0058, 1.13058>
    <6.98039, 1.00805>
    <6.95269, 0.886059>
    <6.92351, 0.764497>
    <6.89201, 0.643564>
    <6.85865, 0.523263>
    <6.82476, 0.403179>
    <6.78569, 0.284759>
    <6.73792, 0.170126>
    <6.66677, 0.070182>
    <6.57482, 0>
    texture { Barrel } }
  matrix <0.999663, 0, 0.00433326, 0, 1, 0, 0.00433326, 0, 1.00036, -2.33826, 0, -1.91694>
}
plane { y, 0 texture { Fixture } }
