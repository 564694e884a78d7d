// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 96.154353, 0.000000>
  direction <0.000000, -1937.362121, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <0.342211, 89.558951, 33.653266> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <-14.293284, 89.558951, 30.469025> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <-26.097818, 89.558951, 21.250019> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <-32.733359, 89.558951, 7.822187> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <-32.885657, 89.558951, -7.154926> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <-26.524548, 89.558951, -20.714917> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <-14.909926, 89.558951, -30.172065> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <-0.342211, 89.558951, -33.653266> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <14.293284, 89.558951, -30.469025> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <26.097818, 89.558951, -21.250019> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <32.733359, 89.558951, -7.822187> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <32.885657, 89.558951, 7.154926> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <26.524548, 89.558951, 20.714917> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
light_source { <14.909926, 89.558951, 30.172065> rgb 0.142857 fade_distance 88.6963 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.0326209 scale <0.548593, 0.0314335, 0.0314335> rotate y * 134.426 translate <-8.286042, -4.944849, 4.527471> }
  finish { ambient 0 emission 0 diffuse 0.894469 specular 0.337356 roughness 0.0750332 metallic reflection { 0.0209889 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 0.814678 scallop_wave scale 0.118165 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.31158 specular 0.0948358 roughness 0.0576877 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.309171 sine_wave scale 0.0704294 translate <-8.286042, -4.944849, 4.527471> }
  finish { ambient 0 emission 0 diffuse 0.392822 specular 0.0627651 roughness 0.070342 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.250767, 0.265042, 0.187993> }
  finish { ambient 0 emission 0 diffuse 0.457867 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.925832 FaceClean] [0.945832 Stain] [1 Stain] }
  scale 0.354113 translate <-14.086271, -8.406244, 7.696702> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.925832 RingClean] [0.945832 Stain] [1 Stain] }
  scale 0.354113 translate <-14.086271, -8.406244, 7.696702> }
#declare Fixture = texture {
  pigment { rgb <0.025381, 0.025381, 0.025514> }
  normal { bumps 0.388874 scale 0.18829 translate <-8.286042, -4.944849, 4.527471> }
  finish { ambient 0 emission 0 diffuse 0.623663 specular 0.134318 roughness 0.0895843 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.39202 * (1 + 0.00349097 * cos(2 * atan2(z, x) + 4.09516) + 0.00165122 * cos(3 * atan2(z, x) + 1.73077)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.29433
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.29433, 7.5>
    <6.39662, 7.48242>
    <6.46718, 7.45511>
    <6.52733, 7.42542>
    <6.58654, 7.3948>
    <6.64319, 7.36302>
    <6.69877, 7.33022>
    <6.75235, 7.2962>
    <6.8036, 7.26085>
    <6.85332, 7.22418>
    <6.90107, 7.18603>
    <6.94671, 7.14629>
    <6.99039, 7.10483>
    <7.03195, 7.06149>
    <7.07146, 7.01611>
    <7.10875, 6.96847>
    <7.14407, 6.91836>
    <7.17682, 6.86543>
    <7.20749, 6.8094>
    <7.23606, 6.74985>
    <7.26236, 6.68626>
    <7.28657, 6.618>
    <7.30805, 6.54417>
    <7.32744, 6.46374>
    <7.34463, 6.3752>
    <7.35957, 6.27642>
    <7.37251, 6.16425>
    <7.38249, 6.03352>
    <7.39045, 5.87526>
    <7.39613, 5.67052>
    <7.39963, 5.36503>
    <7.40125, 3.75>
    <7.39963, 2.13497>
    <7.39613, 1.82948>
    <7.39045, 1.62474>
    <7.38249, 1.46648>
    <7.37251, 1.33575>
    <7.35957, 1.22358>
    <7.34463, 1.1248>
    <7.32744, 1.03626>
    <7.30805, 0.955832>
    <7.28657, 0.882>
    <7.26236, 0.813737>
    <7.23606, 0.750145>
    <7.20749, 0.690598>
    <7.17682, 0.634566>
    <7.14407, 0.581639>
    <7.10875, 0.531528>
    <7.07146, 0.483889>
    <7.03195, 0.438508>
    <6.99039, 0.395168>
    <6.94671, 0.353713>
    <6.90107, 0.313965>
    <6.85332, 0.275824>
    <6.8036, 0.239153>
    <6.75235, 0.203799>
    <6.69877, 0.16978>
    <6.64319, 0.136981>
    <6.58654, 0.105197>
    <6.52733, 0.0745797>
    <6.46718, 0.0448885>
    <6.39662, 0.0175811>
    <6.29433, 0>
    texture { Barrel } }
  matrix <0.992864, 0, -0.00035724, 0, 1, 0, -0.00035724, 0, 1.00719, -2.68627, 0, -0.469525>
}
plane { y, 0 texture { Fixture } }
