// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 98.361494, 0.000000>
  direction <0.000000, -2319.990090, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <18.903994, 90.574371, 26.761190> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <11.950306, 90.574371, 30.507580> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <4.302110, 90.574371, 32.480981> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-3.596109, 90.574371, 32.566705> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-11.285335, 90.574371, 30.759771> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-18.318699, 90.574371, 27.165190> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-24.287446, 90.574371, 21.991868> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-28.844695, 90.574371, 15.540458> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-31.725596, 90.574371, 8.185893> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-32.762720, 90.574371, 0.355594> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-31.895794, 90.574371, -7.495371> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-29.175201, 90.574371, -14.910733> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-24.759050, 90.574371, -21.459536> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-18.903994, 90.574371, -26.761190> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-11.950306, 90.574371, -30.507580> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <-4.302110, 90.574371, -32.480981> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <3.596109, 90.574371, -32.566705> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <11.285335, 90.574371, -30.759771> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <18.318699, 90.574371, -27.165190> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <24.287446, 90.574371, -21.991868> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <28.844695, 90.574371, -15.540458> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <31.725596, 90.574371, -8.185893> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <32.762720, 90.574371, -0.355594> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <31.895794, 90.574371, 7.495371> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <29.175201, 90.574371, 14.910733> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
light_source { <24.759050, 90.574371, 21.459536> rgb 0.0769231 fade_distance 90.8631 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { bumps 0.0473532 scale <0.168479, 0.0137071, 0.0137071> rotate y * 98.8826 translate <21.773826, -43.080391, -8.318312> }
  finish { ambient 0 emission 0 diffuse 0.66542 specular 0.141578 roughness 0.0472848 metallic }
}
#declare RingClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { onion 1.19067 scallop_wave scale 0.160366 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.728492 specular 0.163006 roughness 0.0775151 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { gradient y 0.193853 sine_wave scale 0.0947713 translate <21.773826, -43.080391, -8.318312> }
  finish { ambient 0 emission 0 diffuse 0.383158 specular 0.156888 roughness 0.089979 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.066754, 0.066754, 0.066171> }
  normal { bumps 0.188947 scale 0.264436 translate <21.773826, -43.080391, -8.318312> }
  finish { ambient 0 emission 0 diffuse 0.869995 specular 0.143907 roughness 0.123349 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.38244 * (1 + 0.00853552 * cos(2 * atan2(z, x) + 2.03372) + 0.00482185 * cos(3 * atan2(z, x) + 1.06655)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.29541
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.29541, 7.5>
    <6.39939, 7.43041>
    <6.48024, 7.33292>
    <6.5499, 7.22513>
    <6.6145, 7.11395>
    <6.67471, 7.00026>
    <6.73164, 6.88485>
    <6.7851, 6.76778>
    <6.83542, 6.6493>
    <6.88316, 6.52974>
    <6.92819, 6.40911>
    <6.97027, 6.28741>
    <7.0097, 6.16481>
    <7.04691, 6.04151>
    <7.08177, 5.91752>
    <7.11407, 5.79282>
    <7.14413, 5.66756>
    <7.1719, 5.54176>
    <7.1975, 5.4155>
    <7.22119, 5.28886>
    <7.24262, 5.16181>
    <7.262, 5.03442>
    <7.2793, 4.90673>
    <7.29479, 4.77881>
    <7.30853, 4.65069>
    <7.32016, 4.52235>
    <7.33014, 4.39386>
    <7.33791, 4.26523>
    <7.34412, 4.13651>
    <7.34857, 4.00772>
    <7.35123, 3.87887>
    <7.35249, 3.75>
    <7.35123, 3.62113>
    <7.34857, 3.49228>
    <7.34412, 3.36349>
    <7.33791, 3.23477>
    <7.33014, 3.10614>
    <7.32016, 2.97765>
    <7.30853, 2.84931>
    <7.29479, 2.72119>
    <7.2793, 2.59327>
    <7.262, 2.46558>
    <7.24262, 2.33819>
    <7.22119, 2.21114>
    <7.1975, 2.0845>
    <7.1719, 1.95824>
    <7.14413, 1.83244>
    <7.11407, 1.70718>
    <7.08177, 1.58248>
    <7.04691, 1.45849>
    <7.0097, 1.33519>
    <6.97027, 1.21259>
    <6.92819, 1.09089>
    <6.88316, 0.970259>
    <6.83542, 0.850698>
    <6.7851, 0.732224>
    <6.73164, 0.61515>
    <6.67471, 0.49974>
    <6.6145, 0.38605>
    <6.5499, 0.274869>
    <6.48024, 0.167083>
    <6.39939, 0.0695935>
    <6.29541, 0>
    texture { Barrel } }
  matrix <0.994313, 0, 0.00160367, 0, 1, 0, 0.00160367, 0, 1.00572, -0.121461, 0, 0.520962>
}
plane { y, 0 texture { Fixture } }
