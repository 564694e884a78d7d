// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 80.713532, 0.000000>
  direction <0.000000, -1597.020810, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-0.654728, 77.493617, -20.815974> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <4.542563, 77.493617, -20.324826> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <9.454429, 77.493617, -18.556595> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <13.772238, 77.493617, -15.622384> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <17.224687, 77.493617, -11.706562> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <19.594845, 77.493617, -7.055173> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <20.733788, 77.493617, -1.960482> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <20.569950, 77.493617, 3.257393> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <19.113626, 77.493617, 8.270595> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <16.456323, 77.493617, 12.764124> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <12.765009, 77.493617, 16.455637> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <8.271622, 77.493617, 19.113181> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <3.258499, 77.493617, 20.569774> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-1.959368, 77.493617, 20.733893> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-7.054120, 77.493617, 19.595225> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-11.705636, 77.493617, 17.225316> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-15.621644, 77.493617, 13.773078> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-18.556086, 77.493617, 9.455427> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-20.324582, 77.493617, 4.543656> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-20.816009, 77.493617, -0.653609> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-19.999490, 77.493617, -5.809806> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-17.926329, 77.493617, -10.600951> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-14.726791, 77.493617, -14.725999> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-10.601915, 77.493617, -17.925759> rgb 0.08 fade_distance 73.268 fade_power 2 }
light_source { <-5.810881, 77.493617, -19.999177> rgb 0.08 fade_distance 73.268 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.106591 scale <0.308429, 0.0298621, 0.0298621> rotate y * 43.84 translate <37.360948, 3.497167, 37.488290> }
  finish { ambient 0 emission 0 diffuse 0.656323 specular 0.17718 roughness 0.0793683 metallic }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 0.526088 scallop_wave scale 0.134215 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.552721 specular 0.236177 roughness 0.0556838 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.365844 sine_wave scale 0.084356 translate <37.360948, 3.497167, 37.488290> }
  finish { ambient 0 emission 0 diffuse 0.328082 specular 0.0917844 roughness 0.0694192 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.732966, 0.732966, 0.715796> }
  normal { bumps 0.154448 scale 0.207545 translate <37.360948, 3.497167, 37.488290> }
  finish { ambient 0 emission 0 diffuse 0.740135 specular 0.0743175 roughness 0.051603 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.51322 * (1 + 0.00105332 * cos(2 * atan2(z, x) + 0.886229) + 0.00255227 * cos(3 * atan2(z, x) + 4.25696)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.33631
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.33631, 7.5>
    <6.43459, 7.42248>
    <6.50443, 7.31624>
    <6.56087, 7.20206>
    <6.61742, 7.08773>
    <6.67132, 6.97209>
    <6.72388, 6.85581>
    <6.77476, 6.73873>
    <6.82306, 6.62055>
    <6.86989, 6.50176>
    <6.91469, 6.38216>
    <6.95745, 6.2618>
    <6.99821, 6.14071>
    <7.03706, 6.01898>
    <7.07395, 5.89661>
    <7.10847, 5.77354>
    <7.14116, 5.64995>
    <7.17143, 5.52571>
    <7.19976, 5.40101>
    <7.22618, 5.27587>
    <7.25034, 5.15025>
    <7.27249, 5.02425>
    <7.29214, 4.89781>
    <7.30992, 4.77109>
    <7.32569, 4.6441>
    <7.33932, 4.51684>
    <7.3511, 4.38938>
    <7.36016, 4.2617>
    <7.36743, 4.1339>
    <7.37262, 4.00599>
    <7.37579, 3.87801>
    <7.37727, 3.75>
    <7.37579, 3.62199>
    <7.37262, 3.49401>
    <7.36743, 3.3661>
    <7.36016, 3.2383>
    <7.3511, 3.11062>
    <7.33932, 2.98316>
    <7.32569, 2.8559>
    <7.30992, 2.72891>
    <7.29214, 2.60219>
    <7.27249, 2.47575>
    <7.25034, 2.34975>
    <7.22618, 2.22413>
    <7.19976, 2.09899>
    <7.17143, 1.97429>
    <7.14116, 1.85005>
    <7.10847, 1.72646>
    <7.07395, 1.60339>
    <7.03706, 1.48102>
    <6.99821, 1.35929>
    <6.95745, 1.2382>
    <6.91469, 1.11784>
    <6.86989, 0.998242>
    <6.82306, 0.879446>
    <6.77476, 0.761266>
    <6.72388, 0.644185>
    <6.67132, 0.527911>
    <6.61742, 0.412265>
    <6.56087, 0.297937>
    <6.50443, 0.183759>
    <6.43459, 0.0775155>
    <6.33631, 0>
    texture { Barrel } }
  matrix <1.00096, 0, -0.00209152, 0, 1, 0, -0.00209152, 0, 0.999041, -1.96726, 0, 2.02749>
}
plane { y, 0 texture { Fixture } }
