// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 86.788859, 0.000000>
  direction <0.000000, -2228.604331, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <18.823731, 85.139740, -15.475453> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <23.142985, 85.139740, -7.630514> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <24.336650, 85.139740, 1.244968> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <22.243516, 85.139740, 9.952310> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <17.146272, 85.139740, 17.315538> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <9.733329, 85.139740, 22.340206> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <1.005845, 85.139740, 24.347706> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <-7.857483, 85.139740, 23.066913> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <-15.659614, 85.139740, 18.670805> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <-21.346828, 85.139740, 11.753102> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <-24.151035, 85.139740, 3.248078> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <-23.693510, 85.139740, -5.695618> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <-20.036046, 85.139740, -13.870089> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <-13.672602, 85.139740, -20.171327> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <-5.462598, 85.139740, -23.748316> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <3.485160, 85.139740, -24.117963> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
light_source { <11.962228, 85.139740, -21.230346> rgb 0.117647 fade_distance 79.3376 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { bumps 0.0722331 scale <0.198874, 0.0255597, 0.0255597> rotate y * 28.5308 translate <30.429362, -49.085164, -0.826782> }
  finish { ambient 0 emission 0 diffuse 0.76834 specular 0.401027 roughness 0.0501424 metallic reflection { 0.0449158 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { onion 0.312815 scallop_wave scale 0.0482292 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.397712 specular 0.188822 roughness 0.0528708 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.830000, 0.850000> }
  normal { gradient y 0.360717 sine_wave scale 0.0332756 translate <30.429362, -49.085164, -0.826782> }
  finish { ambient 0 emission 0 diffuse 0.304597 specular 0.0988259 roughness 0.090282 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.394753, 0.318624, 0.159258> }
  finish { ambient 0 emission 0 diffuse 0.418913 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.939305 FaceClean] [0.959305 Stain] [1 Stain] }
  scale 0.832891 translate <51.729916, -83.444779, -1.405530> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.939305 RingClean] [0.959305 Stain] [1 Stain] }
  scale 0.832891 translate <51.729916, -83.444779, -1.405530> }
#declare Fixture = texture {
  pigment { rgb <0.663893, 0.663893, 0.682320> }
  normal { bumps 0.119225 scale 0.164977 translate <30.429362, -49.085164, -0.826782> }
  finish { ambient 0 emission 0 diffuse 0.721453 specular 0.09043 roughness 0.18104 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.56024 * (1 + 0.00977232 * cos(2 * atan2(z, x) + 5.32926) + 0.00510667 * cos(3 * atan2(z, x) + 5.59093)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.70573
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.70573, 7.5>
    <6.77176, 7.40287>
    <6.82095, 7.29335>
    <6.85861, 7.17642>
    <6.8889, 7.05712>
    <6.91573, 6.93688>
    <6.94002, 6.81626>
    <6.96357, 6.69547>
    <6.98483, 6.5742>
    <7.005, 6.45276>
    <7.02345, 6.33099>
    <7.04072, 6.20905>
    <7.05676, 6.08691>
    <7.07164, 5.96461>
    <7.08546, 5.84218>
    <7.09821, 5.71962>
    <7.11007, 5.59695>
    <7.1208, 5.47418>
    <7.13089, 5.35134>
    <7.13976, 5.2284>
    <7.14815, 5.10542>
    <7.15537, 4.98235>
    <7.16211, 4.85925>
    <7.16782, 4.7361>
    <7.17298, 4.61291>
    <7.17732, 4.4897>
    <7.18101, 4.36645>
    <7.18405, 4.24319>
    <7.1863, 4.1199>
    <7.18808, 3.99661>
    <7.18893, 3.87331>
    <7.18952, 3.75>
    <7.18893, 3.62669>
    <7.18808, 3.50339>
    <7.1863, 3.3801>
    <7.18405, 3.25681>
    <7.18101, 3.13355>
    <7.17732, 3.0103>
    <7.17298, 2.88709>
    <7.16782, 2.7639>
    <7.16211, 2.64075>
    <7.15537, 2.51765>
    <7.14815, 2.39458>
    <7.13976, 2.2716>
    <7.13089, 2.14866>
    <7.1208, 2.02582>
    <7.11007, 1.90305>
    <7.09821, 1.78038>
    <7.08546, 1.65782>
    <7.07164, 1.53539>
    <7.05676, 1.41309>
    <7.04072, 1.29095>
    <7.02345, 1.16901>
    <7.005, 1.04724>
    <6.98483, 0.925795>
    <6.96357, 0.804534>
    <6.94002, 0.683736>
    <6.91573, 0.563119>
    <6.8889, 0.442878>
    <6.85861, 0.323584>
    <6.82095, 0.206646>
    <6.77176, 0.0971294>
    <6.70573, 0>
    texture { Barrel } }
  matrix <0.998945, 0, -0.00202772, 0, 1, 0, -0.00202772, 0, 1.00106, -2.78065, 0, -0.0622312>
}
plane { y, 0 texture { Fixture } }
