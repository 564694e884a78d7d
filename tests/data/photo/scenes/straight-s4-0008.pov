// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 57.072565, 0.000000>
  direction <0.000000, -1280.534401, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-23.128913, 54.154288, -21.057477> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <-13.309982, 54.154288, -28.305624> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <-1.464727, 54.154288, -31.244496> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <10.603520, 54.154288, -29.426677> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <21.057477, 54.154288, -23.128913> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <28.305624, 54.154288, -13.309982> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <31.244496, 54.154288, -1.464727> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <29.426677, 54.154288, 10.603520> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <23.128913, 54.154288, 21.057477> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <13.309982, 54.154288, 28.305624> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <1.464727, 54.154288, 31.244496> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <-10.603520, 54.154288, 29.426677> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <-21.057477, 54.154288, 23.128913> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <-28.305624, 54.154288, 13.309982> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <-31.244496, 54.154288, 1.464727> rgb 0.125 fade_distance 49.6158 fade_power 2 }
light_source { <-29.426677, 54.154288, -10.603520> rgb 0.125 fade_distance 49.6158 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.0431708 scale <0.264157, 0.0245938, 0.0245938> rotate y * 98.3344 translate <18.164026, 20.465677, -24.170664> }
  finish { ambient 0 emission 0 diffuse 0.409631 specular 0.2156 roughness 0.0493461 metallic reflection { 0.0413817 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 0.747562 scallop_wave scale 0.160083 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.0992522 specular 0.77814 roughness 0.00756877 metallic reflection { 0.482512 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.21451 sine_wave scale 0.0988729 translate <18.164026, 20.465677, -24.170664> }
  finish { ambient 0 emission 0 diffuse 0.836036 specular 0.224513 roughness 0.0753396 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.334082, 0.267729, 0.151892> }
  finish { ambient 0 emission 0 diffuse 0.499387 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.959298 FaceClean] [0.979298 Stain] [1 Stain] }
  scale 1.10448 translate <30.878844, 34.791650, -41.090129> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.959298 RingClean] [0.979298 Stain] [1 Stain] }
  scale 1.10448 translate <30.878844, 34.791650, -41.090129> }
#declare Fixture = texture {
  pigment { rgb <0.797913, 0.797913, 0.802700> }
  normal { bumps 0.15538 scale 0.115606 translate <18.164026, 20.465677, -24.170664> }
  finish { ambient 0 emission 0 diffuse 0.742079 specular 0.0942263 roughness 0.0985607 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.40577 * (1 + 0.0040509 * cos(2 * atan2(z, x) + 2.9024) + 0.00284372 * cos(3 * atan2(z, x) + 4.75265)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.64323
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.64323, 7.5>
    <6.72356, 7.42354>
    <6.7807, 7.31881>
    <6.82258, 7.2028>
    <6.85635, 7.08355>
    <6.88546, 6.96272>
    <6.91353, 6.84192>
    <6.94069, 6.72073>
    <6.96586, 6.59911>
    <6.98998, 6.47721>
    <7.01229, 6.35489>
    <7.03348, 6.23235>
    <7.05338, 6.10954>
    <7.0721, 5.98651>
    <7.0895, 5.86325>
    <7.10583, 5.73981>
    <7.12095, 5.61618>
    <7.13498, 5.49241>
    <7.14801, 5.36849>
    <7.15981, 5.24444>
    <7.17082, 5.12029>
    <7.1805, 4.99601>
    <7.18953, 4.87167>
    <7.19717, 4.74722>
    <7.20414, 4.62271>
    <7.20997, 4.49814>
    <7.21499, 4.37353>
    <7.21906, 4.24887>
    <7.22218, 4.12418>
    <7.22454, 3.99947>
    <7.22578, 3.87474>
    <7.2265, 3.75>
    <7.22578, 3.62526>
    <7.22454, 3.50053>
    <7.22218, 3.37582>
    <7.21906, 3.25113>
    <7.21499, 3.12647>
    <7.20997, 3.00186>
    <7.20414, 2.87729>
    <7.19717, 2.75278>
    <7.18953, 2.62833>
    <7.1805, 2.50399>
    <7.17082, 2.37971>
    <7.15981, 2.25556>
    <7.14801, 2.13151>
    <7.13498, 2.00759>
    <7.12095, 1.88382>
    <7.10583, 1.76019>
    <7.0895, 1.63675>
    <7.0721, 1.51349>
    <7.05338, 1.39046>
    <7.03348, 1.26765>
    <7.01229, 1.14511>
    <6.98998, 1.02279>
    <6.96586, 0.900891>
    <6.94069, 0.779266>
    <6.91353, 0.65808>
    <6.88546, 0.537277>
    <6.85635, 0.416448>
    <6.82258, 0.297199>
    <6.7807, 0.181188>
    <6.72356, 0.076458>
    <6.64323, 0>
    texture { Barrel } }
  matrix <0.999779, 0, 0.00130615, 0, 1, 0, 0.00130615, 0, 1.00022, -1.99699, 0, 0.550513>
}
plane { y, 0 texture { Fixture } }
