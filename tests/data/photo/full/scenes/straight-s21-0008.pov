// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 86.005514, 0.000000>
  direction <0.000000, -4307.240955, 0.000000>
  right <1456.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 1088.000000> }
light_source { <-22.075803, 80.194955, 8.192719> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <-23.509883, 80.194955, 1.321783> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <-22.855007, 80.194955, -5.666600> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <-20.169364, 80.194955, -12.151481> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <-15.691584, 80.194955, -17.556649> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <-9.819537, 80.194955, -21.401832> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <-3.074982, 80.194955, -23.345368> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <3.942798, 80.194955, -23.214566> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <10.610244, 80.194955, -21.021047> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <16.334923, 80.194955, -16.959717> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <20.608173, 80.194955, -11.391441> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <23.050296, 80.194955, -4.810986> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <23.444299, 80.194955, 2.196947> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <21.755173, 80.194955, 9.009671> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <18.133004, 80.194955, 15.021846> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <12.899639, 80.194955, 19.699265> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <6.520084, 80.194955, 22.626317> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <-0.438809, 80.194955, 23.542922> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <-7.358712, 80.194955, 22.367634> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <-13.624761, 80.194955, 19.204885> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
light_source { <-18.680190, 80.194955, 14.335697> rgb 0.0952381 fade_distance 78.5208 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { bumps 0.0979652 scale <0.114088, 0.0193542, 0.0193542> rotate y * 24.1498 translate <-13.677601, -30.969538, 14.109552> }
  finish { ambient 0 emission 0 diffuse 0.429591 specular 0.11256 roughness 0.0660826 metallic reflection { 0.0620906 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { onion 0.623093 scallop_wave scale 0.163061 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.0876246 specular 0.509498 roughness 0.011311 metallic reflection { 0.31504 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { gradient y 0.376532 sine_wave scale 0.131645 translate <-13.677601, -30.969538, 14.109552> }
  finish { ambient 0 emission 0 diffuse 0.843319 specular 0.159513 roughness 0.0770406 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.727067, 0.727067, 0.740280> }
  normal { bumps 0.165674 scale 0.21672 translate <-13.677601, -30.969538, 14.109552> }
  finish { ambient 0 emission 0 diffuse 0.708661 specular 0.107305 roughness 0.0761951 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.3209 * (1 + 0.00100432 * cos(2 * atan2(z, x) + 2.80603) + 0.00449729 * cos(3 * atan2(z, x) + 2.80103)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.28366
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.28366, 7.5>
    <6.39271, 7.43957>
    <6.4793, 7.34739>
    <6.55293, 7.24199>
    <6.62015, 7.1319>
    <6.68279, 7.01904>
    <6.74045, 6.90349>
    <6.79484, 6.78631>
    <6.84574, 6.66756>
    <6.89301, 6.54725>
    <6.9376, 6.4259>
    <6.97897, 6.30339>
    <7.01731, 6.17986>
    <7.05353, 6.05568>
    <7.08681, 5.93066>
    <7.11769, 5.805>
    <7.14621, 5.67878>
    <7.17256, 5.55207>
    <7.19671, 5.42491>
    <7.21873, 5.29736>
    <7.23867, 5.16945>
    <7.25659, 5.04124>
    <7.27271, 4.91278>
    <7.28704, 4.78411>
    <7.29964, 4.65525>
    <7.31036, 4.52621>
    <7.31928, 4.39703>
    <7.3265, 4.26775>
    <7.33215, 4.13838>
    <7.33621, 4.00896>
    <7.33868, 3.87949>
    <7.33972, 3.75>
    <7.33868, 3.62051>
    <7.33621, 3.49104>
    <7.33215, 3.36162>
    <7.3265, 3.23225>
    <7.31928, 3.10297>
    <7.31036, 2.97379>
    <7.29964, 2.84475>
    <7.28704, 2.71589>
    <7.27271, 2.58722>
    <7.25659, 2.45876>
    <7.23867, 2.33055>
    <7.21873, 2.20264>
    <7.19671, 2.07509>
    <7.17256, 1.94793>
    <7.14621, 1.82122>
    <7.11769, 1.695>
    <7.08681, 1.56934>
    <7.05353, 1.44432>
    <7.01731, 1.32014>
    <6.97897, 1.19661>
    <6.9376, 1.0741>
    <6.89301, 0.952747>
    <6.84574, 0.832442>
    <6.79484, 0.713687>
    <6.74045, 0.596513>
    <6.68279, 0.480957>
    <6.62015, 0.368102>
    <6.55293, 0.258007>
    <6.4793, 0.152614>
    <6.39271, 0.0604298>
    <6.28366, 0>
    texture { Barrel } }
  matrix <0.99755, 0, 0.000716899, 0, 1, 0, 0.000716899, 0, 1.00246, -1.49137, 0, -0.422044>
}
plane { y, 0 texture { Fixture } }
