// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 86.548223, 0.000000>
  direction <0.000000, -4297.553289, 0.000000>
  right <1456.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 1088.000000> }
light_source { <-21.060974, 79.443396, 19.053462> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-25.137708, 79.443396, 13.217212> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-27.634948, 79.443396, 6.550475> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-28.395782, 79.443396, -0.527852> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-27.372405, 79.443396, -7.573013> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-24.629118, 79.443396, -14.142333> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-20.338294, 79.443396, -19.823038> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-14.769540, 79.443396, -24.258189> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-8.272762, 79.443396, -27.169109> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-1.256175, 79.443396, -28.372893> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <5.839342, 79.443396, -27.793905> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <12.567951, 79.443396, -25.468523> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <18.506870, 79.443396, -21.542860> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <23.282934, 79.443396, -16.263580> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <26.596046, 79.443396, -9.962400> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <28.238030, 79.443396, -3.035245> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <28.105715, 79.443396, 4.082625> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <26.207415, 79.443396, 10.943969> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <22.662406, 79.443396, 17.117663> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <17.693435, 79.443396, 22.215792> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <11.612721, 79.443396, 25.918020> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <4.802336, 79.443396, 27.991724> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-2.309797, 79.443396, 28.306605> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-9.276797, 79.443396, 26.842878> rgb 0.08 fade_distance 79.074 fade_power 2 }
light_source { <-15.660901, 79.443396, 23.692514> rgb 0.08 fade_distance 79.074 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.103811 scale <0.189988, 0.0133219, 0.0133219> rotate y * 109.284 translate <-1.631012, 24.651502, -48.905506> }
  finish { ambient 0 emission 0 diffuse 0.87586 specular 0.272738 roughness 0.0472569 metallic reflection { 0.0538398 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 1.25963 scallop_wave scale 0.122077 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.340617 specular 0.0891452 roughness 0.0531664 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.169867 sine_wave scale 0.072022 translate <-1.631012, 24.651502, -48.905506> }
  finish { ambient 0 emission 0 diffuse 0.293279 specular 0.129531 roughness 0.088124 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.386827, 0.248475, 0.245991> }
  finish { ambient 0 emission 0 diffuse 0.581989 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.926868 FaceClean] [0.946868 Stain] [1 Stain] }
  scale 0.354505 translate <-2.772721, 41.907554, -83.139360> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.926868 RingClean] [0.946868 Stain] [1 Stain] }
  scale 0.354505 translate <-2.772721, 41.907554, -83.139360> }
#declare Fixture = texture {
  pigment { rgb <0.728247, 0.728247, 0.737614> }
  normal { bumps 0.101427 scale 0.135452 translate <-1.631012, 24.651502, -48.905506> }
  finish { ambient 0 emission 0 diffuse 0.877664 specular 0.0646865 roughness 0.192703 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.98169 * (1 + 0.000335324 * cos(2 * atan2(z, x) + 2.07899) + 0.00418971 * cos(3 * atan2(z, x) + 2.06715)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.4826
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.4826, 7.5>
    <6.57728, 7.42374>
    <6.6449, 7.31874>
    <6.69618, 7.20412>
    <6.73981, 7.08642>
    <6.78176, 6.9682>
    <6.82218, 6.84926>
    <6.86127, 6.72989>
    <6.89856, 6.60985>
    <6.93398, 6.48921>
    <6.96771, 6.36805>
    <6.99984, 6.24642>
    <7.03018, 6.12429>
    <7.05896, 6.00176>
    <7.08612, 5.87883>
    <7.11154, 5.75548>
    <7.13534, 5.63178>
    <7.15768, 5.50777>
    <7.17821, 5.38343>
    <7.19729, 5.25883>
    <7.21465, 5.13395>
    <7.23046, 5.00885>
    <7.2448, 4.88354>
    <7.25746, 4.75804>
    <7.26885, 4.6324>
    <7.27842, 4.50659>
    <7.28667, 4.38068>
    <7.29319, 4.25465>
    <7.29837, 4.12856>
    <7.30212, 4.00241>
    <7.30431, 3.87621>
    <7.30539, 3.75>
    <7.30431, 3.62379>
    <7.30212, 3.49759>
    <7.29837, 3.37144>
    <7.29319, 3.24535>
    <7.28667, 3.11932>
    <7.27842, 2.99341>
    <7.26885, 2.8676>
    <7.25746, 2.74196>
    <7.2448, 2.61646>
    <7.23046, 2.49115>
    <7.21465, 2.36605>
    <7.19729, 2.24117>
    <7.17821, 2.11657>
    <7.15768, 1.99223>
    <7.13534, 1.86822>
    <7.11154, 1.74452>
    <7.08612, 1.62117>
    <7.05896, 1.49824>
    <7.03018, 1.37571>
    <6.99984, 1.25358>
    <6.96771, 1.13195>
    <6.93398, 1.01079>
    <6.89856, 0.890153>
    <6.86127, 0.770112>
    <6.82218, 0.650737>
    <6.78176, 0.531802>
    <6.73981, 0.413582>
    <6.69618, 0.295882>
    <6.6449, 0.181259>
    <6.57728, 0.0762596>
    <6.4826, 0>
    texture { Barrel } }
  matrix <0.993887, 0, 0.00299458, 0, 1, 0, 0.00299458, 0, 1.00616, 1.96011, 0, -0.485101>
}
plane { y, 0 texture { Fixture } }
