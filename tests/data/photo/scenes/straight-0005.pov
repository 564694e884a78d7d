// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 63.042099, 0.000000>
  direction <0.000000, -1356.351137, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <15.098285, 57.171397, -27.517852> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <20.176642, 57.171397, -24.043575> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <24.479622, 57.171397, -19.645317> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <27.841864, 57.171397, -14.492101> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <30.134159, 57.171397, -8.781961> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <31.268415, 57.171397, -2.734335> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <31.201044, 57.171397, 3.418370> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <29.934634, 57.171397, 9.439709> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <27.517852, 57.171397, 15.098285> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <24.043575, 57.171397, 20.176642> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <19.645317, 57.171397, 24.479622> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <14.492101, 57.171397, 27.841864> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <8.781961, 57.171397, 30.134159> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <2.734335, 57.171397, 31.268415> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-3.418370, 57.171397, 31.201044> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-9.439709, 57.171397, 29.934634> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-15.098285, 57.171397, 27.517852> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-20.176642, 57.171397, 24.043575> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-24.479622, 57.171397, 19.645317> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-27.841864, 57.171397, 14.492101> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-30.134159, 57.171397, 8.781961> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-31.268415, 57.171397, 2.734335> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-31.201044, 57.171397, -3.418370> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-29.934634, 57.171397, -9.439709> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-27.517852, 57.171397, -15.098285> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-24.043575, 57.171397, -20.176642> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-19.645317, 57.171397, -24.479622> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-14.492101, 57.171397, -27.841864> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-8.781961, 57.171397, -30.134159> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <-2.734335, 57.171397, -31.268415> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <3.418370, 57.171397, -31.201044> rgb 0.0625 fade_distance 55.675 fade_power 2 }
light_source { <9.439709, 57.171397, -29.934634> rgb 0.0625 fade_distance 55.675 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { bumps 0.0935411 scale <0.254027, 0.03848, 0.03848> rotate y * 42.072 translate <37.500994, 1.500633, -18.590853> }
  finish { ambient 0 emission 0 diffuse 0.417798 specular 0.298719 roughness 0.0459383 metallic }
}
#declare RingClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { onion 0.492591 scallop_wave scale 0.194057 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.375616 specular 0.240233 roughness 0.0572867 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { gradient y 0.31131 sine_wave scale 0.111841 translate <37.500994, 1.500633, -18.590853> }
  finish { ambient 0 emission 0 diffuse 0.539788 specular 0.192357 roughness 0.0640938 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.285002, 0.317134, 0.178269> }
  finish { ambient 0 emission 0 diffuse 0.401103 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.8522 FaceClean] [0.8722 Stain] [1 Stain] }
  scale 0.555454 translate <63.751689, 2.551076, -31.604450> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.8522 RingClean] [0.8722 Stain] [1 Stain] }
  scale 0.555454 translate <63.751689, 2.551076, -31.604450> }
#declare Fixture = texture {
  pigment { rgb <0.583143, 0.583143, 0.598217> }
  normal { bumps 0.291727 scale 0.183165 translate <37.500994, 1.500633, -18.590853> }
  finish { ambient 0 emission 0 diffuse 0.799619 specular 0.106393 roughness 0.116196 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.0006 * (1 + 0.00777919 * cos(2 * atan2(z, x) + 4.44686) + 0.00525582 * cos(3 * atan2(z, x) + 3.4184)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.47649
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.47649, 7.5>
    <6.58835, 7.46965>
    <6.66693, 7.37569>
    <6.72223, 7.26299>
    <6.77128, 7.14674>
    <6.81385, 7.02744>
    <6.85731, 6.90847>
    <6.89445, 6.78698>
    <6.9306, 6.66511>
    <6.9636, 6.54217>
    <6.99413, 6.41845>
    <7.02284, 6.2942>
    <7.04951, 6.16939>
    <7.07433, 6.04412>
    <7.09722, 5.91841>
    <7.11845, 5.79233>
    <7.13785, 5.66591>
    <7.15588, 5.53923>
    <7.17234, 5.41229>
    <7.18736, 5.28514>
    <7.20112, 5.15781>
    <7.21335, 5.03029>
    <7.22457, 4.90266>
    <7.23409, 4.77485>
    <7.24265, 4.64697>
    <7.24984, 4.51898>
    <7.25601, 4.39093>
    <7.26098, 4.26281>
    <7.26483, 4.13465>
    <7.26767, 4.00646>
    <7.26926, 3.87823>
    <7.27005, 3.75>
    <7.26926, 3.62177>
    <7.26767, 3.49354>
    <7.26483, 3.36535>
    <7.26098, 3.23719>
    <7.25601, 3.10907>
    <7.24984, 2.98102>
    <7.24265, 2.85303>
    <7.23409, 2.72515>
    <7.22457, 2.59734>
    <7.21335, 2.46971>
    <7.20112, 2.34219>
    <7.18736, 2.21486>
    <7.17234, 2.08771>
    <7.15588, 1.96077>
    <7.13785, 1.83409>
    <7.11845, 1.70767>
    <7.09722, 1.58159>
    <7.07433, 1.45588>
    <7.04951, 1.33061>
    <7.02284, 1.2058>
    <6.99413, 1.08155>
    <6.9636, 0.957825>
    <6.9306, 0.834888>
    <6.89445, 0.713016>
    <6.85731, 0.591528>
    <6.81385, 0.472561>
    <6.77128, 0.353263>
    <6.72223, 0.237008>
    <6.66693, 0.124313>
    <6.58835, 0.0303491>
    <6.47649, 0>
    texture { Barrel } }
  matrix <0.998258, 0, 0.00693046, 0, 1, 0, 0.00693046, 0, 1.00179, 3.66385, 0, 1.16359>
}
plane { y, 0 texture { Fixture } }
