// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <-14.949430, 76.560960, 0.700762>
  direction <314.496517, -1533.273292, -20.840405>
  right <626.949166, 128.584582, 0.864826>
  up <0.648619, -6.390583, 479.957019> }
light_source { <1.273098, 76.141849, -0.943073> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <0.955314, 76.005735, 4.275552> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-1.005620, 75.537925, 9.101466> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-4.397205, 74.789113, 13.011707> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-8.851910, 73.840446, 15.582540> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-13.886999, 72.794725, 16.535375> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-18.956843, 71.765271, 15.766958> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-23.512044, 70.863642, 13.360559> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-27.058976, 70.187542, 9.576948> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-29.213275, 69.810238, 4.826138> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-29.741487, 69.772616, -0.377047> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-28.586374, 70.078753, -5.468760> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-25.873109, 70.695475, -9.897236> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-21.895718, 71.555951, -13.182581> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-17.085211, 72.566933, -14.968777> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-11.962883, 73.618867, -15.062261> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-7.083817, 74.597760, -13.452903> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-2.976735, 75.397533, -10.315102> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
light_source { <-0.086703, 75.931517, -5.988888> rgb 0.105263 fade_distance 70.6639 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.0249345 scale <0.222041, 0.0357397, 0.0357397> rotate y * 169.082 translate <1.547473, 30.357379, -34.294299> }
  finish { ambient 0 emission 0 diffuse 0.124649 specular 0.760578 roughness 0.0151447 metallic reflection { 0.403919 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 0.987253 scallop_wave scale 0.0986213 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.585994 specular 0.198762 roughness 0.0946045 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.362635 sine_wave scale 0.0646086 translate <1.547473, 30.357379, -34.294299> }
  finish { ambient 0 emission 0 diffuse 0.57415 specular 0.180062 roughness 0.0711702 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.351680, 0.246150, 0.224847> }
  finish { ambient 0 emission 0 diffuse 0.45697 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.872902 FaceClean] [0.892902 Stain] [1 Stain] }
  scale 1.02012 translate <2.630705, 51.607544, -58.300308> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.872902 RingClean] [0.892902 Stain] [1 Stain] }
  scale 1.02012 translate <2.630705, 51.607544, -58.300308> }
#declare Fixture = texture {
  pigment { rgb <0.036519, 0.036519, 0.037523> }
  normal { bumps 0.161574 scale 0.155611 translate <1.547473, 30.357379, -34.294299> }
  finish { ambient 0 emission 0 diffuse 0.805065 specular 0.076211 roughness 0.194638 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.04457 * (1 + 0.00212606 * cos(2 * atan2(z, x) + 6.092) + 0.000975759 * cos(3 * atan2(z, x) + 0.605155)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.19746
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.19746, 7.5>
    <6.31163, 7.44099>
    <6.38933, 7.33711>
    <6.46027, 7.22818>
    <6.52622, 7.11602>
    <6.58914, 7.002>
    <6.65125, 6.88754>
    <6.71066, 6.7716>
    <6.76763, 6.65439>
    <6.8228, 6.5363>
    <6.8759, 6.41723>
    <6.92667, 6.2971>
    <6.97529, 6.17606>
    <7.02138, 6.05398>
    <7.06521, 5.93105>
    <7.10685, 5.80732>
    <7.14637, 5.68287>
    <7.18303, 5.55751>
    <7.21729, 5.43145>
    <7.24915, 5.30473>
    <7.27866, 5.17742>
    <7.30594, 5.04959>
    <7.33016, 4.92111>
    <7.35194, 4.79218>
    <7.37122, 4.66284>
    <7.38807, 4.53313>
    <7.40271, 4.40315>
    <7.41404, 4.27281>
    <7.423, 4.14229>
    <7.42939, 4.01162>
    <7.43336, 3.88084>
    <7.43519, 3.75>
    <7.43336, 3.61916>
    <7.42939, 3.48838>
    <7.423, 3.35771>
    <7.41404, 3.22719>
    <7.40271, 3.09685>
    <7.38807, 2.96687>
    <7.37122, 2.83716>
    <7.35194, 2.70782>
    <7.33016, 2.57889>
    <7.30594, 2.45041>
    <7.27866, 2.32258>
    <7.24915, 2.19527>
    <7.21729, 2.06855>
    <7.18303, 1.94249>
    <7.14637, 1.81713>
    <7.10685, 1.69268>
    <7.06521, 1.56895>
    <7.02138, 1.44602>
    <6.97529, 1.32394>
    <6.92667, 1.2029>
    <6.8759, 1.08277>
    <6.8228, 0.963701>
    <6.76763, 0.845606>
    <6.71066, 0.728401>
    <6.65125, 0.612461>
    <6.58914, 0.497997>
    <6.52622, 0.383983>
    <6.46027, 0.271818>
    <6.38933, 0.162888>
    <6.31163, 0.0590079>
    <6.19746, 0>
    texture { Barrel } }
  matrix <0.998725, 0, -0.00290674, 0, 1, 0, -0.00290674, 0, 1.00128, 0, 0, 0>
}
plane { y, 0 texture { Fixture } }
