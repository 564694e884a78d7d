// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 80.135166, 0.000000>
  direction <0.000000, -1803.552628, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-1.451681, 73.457956, 17.764644> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <-6.623408, 73.457956, 16.547520> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <-11.206616, 73.457956, 13.860077> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <-14.794067, 73.457956, 9.941104> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <-17.067000, 73.457956, 5.138821> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <-17.823455, 73.457956, -0.120069> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <-16.996218, 73.457956, -5.368290> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <-14.658793, 73.457956, -10.139515> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <-11.018869, 73.457956, -14.009800> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <-6.399871, 73.457956, -16.635252> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <-1.212216, 73.457956, -17.782590> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <4.083150, 73.457956, -17.349866> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <9.015710, 73.457956, -15.375530> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <13.147184, 73.457956, -12.035012> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <16.110474, 73.457956, -7.625129> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <17.642277, 73.457956, -2.537721> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <17.606486, 73.457956, 2.775176> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <16.006282, 73.457956, 7.841485> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <12.983850, 73.457956, 12.211045> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <8.807745, 73.457956, 15.495599> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
light_source { <3.849034, 73.457956, 17.403301> rgb 0.0952381 fade_distance 72.6387 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { bumps 0.0493977 scale <0.0872648, 0.0150117, 0.0150117> rotate y * 151.488 translate <49.920829, 45.281241, 20.617142> }
  finish { ambient 0 emission 0 diffuse 0.483235 specular 0.213293 roughness 0.0756759 metallic }
}
#declare RingClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { onion 0.559639 scallop_wave scale 0.076432 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.567405 specular 0.289168 roughness 0.058122 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { gradient y 0.35203 sine_wave scale 0.0542284 translate <49.920829, 45.281241, 20.617142> }
  finish { ambient 0 emission 0 diffuse 0.310469 specular 0.117672 roughness 0.0995607 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.490596, 0.490596, 0.481045> }
  normal { bumps 0.251291 scale 0.156053 translate <49.920829, 45.281241, 20.617142> }
  finish { ambient 0 emission 0 diffuse 0.740558 specular 0.0588691 roughness 0.115703 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.5159 * (1 + 0.00141171 * cos(2 * atan2(z, x) + 0.945429) + 0.00175475 * cos(3 * atan2(z, x) + 0.397538)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.67998
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.67998, 7.5>
    <6.75291, 7.40568>
    <6.80866, 7.29812>
    <6.85034, 7.1825>
    <6.8827, 7.06345>
    <6.91167, 6.94351>
    <6.93745, 6.82285>
    <6.96273, 6.70212>
    <6.98499, 6.58071>
    <7.00616, 6.45912>
    <7.02519, 6.33712>
    <7.04292, 6.21493>
    <7.05928, 6.09253>
    <7.07434, 5.96995>
    <7.08829, 5.84722>
    <7.10107, 5.72436>
    <7.1129, 5.60139>
    <7.12355, 5.47831>
    <7.13351, 5.35516>
    <7.14225, 5.23191>
    <7.15048, 5.10862>
    <7.15752, 4.98526>
    <7.16408, 4.86186>
    <7.16963, 4.7384>
    <7.17464, 4.61493>
    <7.17885, 4.49141>
    <7.1824, 4.36788>
    <7.18534, 4.24433>
    <7.1875, 4.12076>
    <7.18923, 3.99718>
    <7.19004, 3.87359>
    <7.19061, 3.75>
    <7.19004, 3.62641>
    <7.18923, 3.50282>
    <7.1875, 3.37924>
    <7.18534, 3.25567>
    <7.1824, 3.13212>
    <7.17885, 3.00859>
    <7.17464, 2.88507>
    <7.16963, 2.7616>
    <7.16408, 2.63814>
    <7.15752, 2.51474>
    <7.15048, 2.39138>
    <7.14225, 2.26809>
    <7.13351, 2.14484>
    <7.12355, 2.02169>
    <7.1129, 1.89861>
    <7.10107, 1.77564>
    <7.08829, 1.65278>
    <7.07434, 1.53005>
    <7.05928, 1.40747>
    <7.04292, 1.28507>
    <7.02519, 1.16288>
    <7.00616, 1.04088>
    <6.98499, 0.919292>
    <6.96273, 0.797879>
    <6.93745, 0.677153>
    <6.91167, 0.556487>
    <6.8827, 0.436548>
    <6.85034, 0.317503>
    <6.80866, 0.201876>
    <6.75291, 0.094319>
    <6.67998, 0>
    texture { Barrel } }
  matrix <1.00068, 0, 0.00026105, 0, 1, 0, 0.00026105, 0, 0.999321, -0.554324, 0, -0.461063>
}
plane { y, 0 texture { Fixture } }
