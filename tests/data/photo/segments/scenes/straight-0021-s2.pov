// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 65.174409, 0.000000>
  direction <0.000000, -1417.020452, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-32.344385, 60.751113, -4.344093> rgb 0.0714286 fade_distance 57.6974 fade_power 2 }
light_source { <-30.566792, 60.751113, -11.432481> rgb 0.0714286 fade_distance 57.6974 fade_power 2 }
light_source { <-27.256453, 60.751113, -17.947596> rgb 0.0714286 fade_distance 57.6974 fade_power 2 }
light_source { <-22.579361, 60.751113, -23.562743> rgb 0.0714286 fade_distance 57.6974 fade_power 2 }
light_source { <-23.562743, 60.751113, 22.579361> rgb 0.0714286 fade_distance 57.6974 fade_power 2 }
light_source { <-27.996357, 60.751113, 16.770045> rgb 0.0714286 fade_distance 57.6974 fade_power 2 }
light_source { <-31.026116, 60.751113, 10.119810> rgb 0.0714286 fade_distance 57.6974 fade_power 2 }
light_source { <-32.500096, 60.751113, 2.962125> rgb 0.0714286 fade_distance 57.6974 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { bumps 0.103638 scale <0.56132, 0.0319195, 0.0319195> rotate y * 170.8 translate <36.197225, 3.057332, 16.001568> }
  finish { ambient 0 emission 0 diffuse 0.768363 specular 0.335064 roughness 0.0498201 metallic reflection { 0.0314796 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { onion 1.27197 scallop_wave scale 0.176797 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.300384 specular 0.143944 roughness 0.0860287 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { gradient y 0.23328 sine_wave scale 0.0957995 translate <36.197225, 3.057332, 16.001568> }
  finish { ambient 0 emission 0 diffuse 0.431905 specular 0.158468 roughness 0.0760738 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.542773, 0.542773, 0.539321> }
  normal { bumps 0.265123 scale 0.212367 translate <36.197225, 3.057332, 16.001568> }
  finish { ambient 0 emission 0 diffuse 0.671327 specular 0.120892 roughness 0.1597 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.1779 * (1 + 0.00183795 * cos(2 * atan2(z, x) + 0.235085) + 0.00492586 * cos(3 * atan2(z, x) + 0.222793)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.24712
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.24712, 7.5>
    <6.35408, 7.42873>
    <6.43489, 7.32864>
    <6.50746, 7.22166>
    <6.57479, 7.11119>
    <6.63781, 6.99816>
    <6.69774, 6.88348>
    <6.75452, 6.76721>
    <6.80842, 6.64959>
    <6.85962, 6.53076>
    <6.90862, 6.411>
    <6.95403, 6.28985>
    <6.99723, 6.16788>
    <7.03813, 6.04512>
    <7.0765, 5.92154>
    <7.11248, 5.79724>
    <7.14589, 5.67222>
    <7.17677, 5.54655>
    <7.20555, 5.42038>
    <7.23218, 5.29373>
    <7.2565, 5.16661>
    <7.27848, 5.03906>
    <7.29802, 4.9111>
    <7.31563, 4.78286>
    <7.33119, 4.65436>
    <7.34462, 4.52561>
    <7.3561, 4.39666>
    <7.36495, 4.26751>
    <7.37206, 4.13824>
    <7.37712, 4.00888>
    <7.38021, 3.87946>
    <7.38164, 3.75>
    <7.38021, 3.62054>
    <7.37712, 3.49112>
    <7.37206, 3.36176>
    <7.36495, 3.23249>
    <7.3561, 3.10334>
    <7.34462, 2.97439>
    <7.33119, 2.84564>
    <7.31563, 2.71714>
    <7.29802, 2.5889>
    <7.27848, 2.46094>
    <7.2565, 2.33339>
    <7.23218, 2.20627>
    <7.20555, 2.07962>
    <7.17677, 1.95345>
    <7.14589, 1.82778>
    <7.11248, 1.70276>
    <7.0765, 1.57846>
    <7.03813, 1.45488>
    <6.99723, 1.33212>
    <6.95403, 1.21015>
    <6.90862, 1.089>
    <6.85962, 0.969238>
    <6.80842, 0.850408>
    <6.75452, 0.732792>
    <6.69774, 0.61652>
    <6.63781, 0.501836>
    <6.57479, 0.388809>
    <6.50746, 0.278341>
    <6.43489, 0.171356>
    <6.35408, 0.0712731>
    <6.24712, 0>
    texture { Barrel } }
  matrix <0.998484, 0, 0.00611497, 0, 1, 0, 0.00611497, 0, 1.00156, 1.62827, 0, -0.0530025>
}
plane { y, 0 texture { Fixture } }
