// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 66.812607, 0.000000>
  direction <0.000000, -1381.698947, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <15.422067, 64.888715, 4.026523> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <14.139418, 64.888715, 7.357303> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <12.147759, 64.888715, 10.319156> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <9.546961, 64.888715, 12.763564> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <6.467439, 64.888715, 14.567954> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <3.063612, 64.888715, 15.641845> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-0.493837, 64.888715, 15.931389> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-4.026523, 64.888715, 15.422067> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-7.357303, 64.888715, 14.139418> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-10.319156, 64.888715, 12.147759> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-12.763564, 64.888715, 9.546961> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-14.567954, 64.888715, 6.467439> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-15.641845, 64.888715, 3.063612> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-15.931389, 64.888715, -0.493837> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-15.422067, 64.888715, -4.026523> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-14.139418, 64.888715, -7.357303> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-12.147759, 64.888715, -10.319156> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-9.546961, 64.888715, -12.763564> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-6.467439, 64.888715, -14.567954> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <-3.063612, 64.888715, -15.641845> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <0.493837, 64.888715, -15.931389> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <4.026523, 64.888715, -15.422067> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <7.357303, 64.888715, -14.139418> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <10.319156, 64.888715, -12.147759> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <12.763564, 64.888715, -9.546961> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <14.567954, 64.888715, -6.467439> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <15.641845, 64.888715, -3.063612> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
light_source { <15.931389, 64.888715, 0.493837> rgb 0.0714286 fade_distance 59.4398 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { bumps 0.0373533 scale <0.619643, 0.0396419, 0.0396419> rotate y * 28.2447 translate <-13.410846, 14.469955, -35.753259> }
  finish { ambient 0 emission 0 diffuse 0.104899 specular 0.601658 roughness 0.0051719 metallic reflection { 0.55651 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { onion 1.23963 scallop_wave scale 0.131559 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.595596 specular 0.101379 roughness 0.0800141 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { gradient y 0.266627 sine_wave scale 0.0701853 translate <-13.410846, 14.469955, -35.753259> }
  finish { ambient 0 emission 0 diffuse 0.519507 specular 0.0902586 roughness 0.0968485 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.253228, 0.316622, 0.234532> }
  finish { ambient 0 emission 0 diffuse 0.321974 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.873449 FaceClean] [0.893449 Stain] [1 Stain] }
  scale 0.595813 translate <-22.798438, 24.598924, -60.780541> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.873449 RingClean] [0.893449 Stain] [1 Stain] }
  scale 0.595813 translate <-22.798438, 24.598924, -60.780541> }
#declare Fixture = texture {
  pigment { rgb <0.066171, 0.066171, 0.065663> }
  normal { bumps 0.102615 scale 0.0870163 translate <-13.410846, 14.469955, -35.753259> }
  finish { ambient 0 emission 0 diffuse 0.771034 specular 0.0723917 roughness 0.0972392 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.40768 * (1 + 0.00603547 * cos(2 * atan2(z, x) + 0.406176) + 0.00570817 * cos(3 * atan2(z, x) + 3.31863)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.62781
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.62781, 7.5>
    <6.7128, 7.41435>
    <6.77851, 7.31055>
    <6.82533, 7.1963>
    <6.86119, 7.07769>
    <6.89336, 6.95795>
    <6.92226, 6.83734>
    <6.95093, 6.71663>
    <6.97585, 6.59503>
    <6.99984, 6.47323>
    <7.02112, 6.35088>
    <7.04111, 6.2283>
    <7.05947, 6.10544>
    <7.07646, 5.98237>
    <7.09209, 5.8591>
    <7.10652, 5.73568>
    <7.11976, 5.6121>
    <7.13182, 5.4884>
    <7.14298, 5.3646>
    <7.15288, 5.24069>
    <7.16212, 5.11672>
    <7.17007, 4.99265>
    <7.17744, 4.86855>
    <7.18369, 4.74437>
    <7.18933, 4.62016>
    <7.19406, 4.49592>
    <7.19808, 4.37164>
    <7.20136, 4.24734>
    <7.20383, 4.12302>
    <7.20573, 3.99869>
    <7.2067, 3.87435>
    <7.20728, 3.75>
    <7.2067, 3.62565>
    <7.20573, 3.50131>
    <7.20383, 3.37698>
    <7.20136, 3.25266>
    <7.19808, 3.12836>
    <7.19406, 3.00408>
    <7.18933, 2.87984>
    <7.18369, 2.75563>
    <7.17744, 2.63145>
    <7.17007, 2.50735>
    <7.16212, 2.38328>
    <7.15288, 2.25931>
    <7.14298, 2.1354>
    <7.13182, 2.0116>
    <7.11976, 1.8879>
    <7.10652, 1.76432>
    <7.09209, 1.6409>
    <7.07646, 1.51763>
    <7.05947, 1.39456>
    <7.04111, 1.2717>
    <7.02112, 1.14912>
    <6.99984, 1.02677>
    <6.97585, 0.904965>
    <6.95093, 0.783369>
    <6.92226, 0.662656>
    <6.89336, 0.542046>
    <6.86119, 0.422312>
    <6.82533, 0.303701>
    <6.77851, 0.189447>
    <6.7128, 0.0856458>
    <6.62781, 0>
    texture { Barrel } }
  matrix <1.00148, 0, -0.00161229, 0, 1, 0, -0.00161229, 0, 0.998522, 3.88225, 0, -0.184848>
}
plane { y, 0 texture { Fixture } }
