// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 55.479195, 0.000000>
  direction <0.000000, -1233.513084, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-20.161496, 53.486188, 22.912018> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-24.901915, 53.486188, 17.644861> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-28.299866, 53.486188, 11.426465> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-30.172163, 53.486188, 4.592065> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-30.417872, 53.486188, -2.489895> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-29.023745, 53.486188, -9.437623> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-26.064940, 53.486188, -15.876567> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-21.700968, 53.486188, -21.459601> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-16.167091, 53.486188, -25.885742> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-9.761642, 53.486188, -28.916377> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-2.829940, 53.486188, -30.388122> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <4.254324, 53.486188, -30.221635> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <11.109237, 53.486188, -28.425892> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <17.365248, 53.486188, -25.097702> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <22.685094, 53.486188, -20.416489> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <26.781981, 53.486188, -14.634617> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <29.435044, 53.486188, -8.063789> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <30.501256, 53.486188, -1.058240> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <29.923138, 53.486188, 6.004358> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <27.731856, 53.486188, 12.743261> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <24.045542, 53.486188, 18.795170> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <19.062926, 53.486188, 23.833828> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <13.052624, 53.486188, 27.587597> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <6.338651, 53.486188, 29.854112> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-0.717040, 53.486188, 30.511184> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-7.734076, 53.486188, 29.523390> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
light_source { <-14.334165, 53.486188, 26.943983> rgb 0.0740741 fade_distance 48.0799 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { bumps 0.114979 scale <0.267109, 0.0177586, 0.0177586> rotate y * 1.95087 translate <36.050500, -29.684710, -32.635806> }
  finish { ambient 0 emission 0 diffuse 0.569176 specular 0.104905 roughness 0.0510568 metallic reflection { 0.052603 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { onion 0.400982 scallop_wave scale 0.10217 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.0590203 specular 0.707131 roughness 0.00528322 metallic reflection { 0.491677 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { gradient y 0.232383 sine_wave scale 0.0497304 translate <36.050500, -29.684710, -32.635806> }
  finish { ambient 0 emission 0 diffuse 0.602832 specular 0.15688 roughness 0.0875116 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.382707, 0.290182, 0.227322> }
  finish { ambient 0 emission 0 diffuse 0.563098 specular 0.05 roughness 0.1 metallic }
}
#declare Face = texture { bozo turbulence 0.6 texture_map { [0 FaceClean] [0.955595 FaceClean] [0.975595 Stain] [1 Stain] }
  scale 1.03855 translate <61.285851, -50.464007, -55.480870> }
#declare Ring = texture { bozo turbulence 0.6 texture_map { [0 RingClean] [0.955595 RingClean] [0.975595 Stain] [1 Stain] }
  scale 1.03855 translate <61.285851, -50.464007, -55.480870> }
#declare Fixture = texture {
  pigment { rgb <0.054176, 0.054176, 0.054743> }
  normal { bumps 0.100662 scale 0.275178 translate <36.050500, -29.684710, -32.635806> }
  finish { ambient 0 emission 0 diffuse 0.750476 specular 0.0250013 roughness 0.0602572 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.25449 * (1 + 0.00672005 * cos(2 * atan2(z, x) + 4.16892) + 0.00236122 * cos(3 * atan2(z, x) + 2.97897)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.56318
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.56318, 7.5>
    <6.6593, 7.43037>
    <6.73073, 7.32926>
    <6.78118, 7.21515>
    <6.82309, 7.0977>
    <6.85993, 6.97827>
    <6.89521, 6.85858>
    <6.92763, 6.7377>
    <6.95727, 6.61618>
    <6.9851, 6.49412>
    <7.01019, 6.37144>
    <7.03375, 6.24841>
    <7.05545, 6.125>
    <7.07555, 6.00128>
    <7.094, 5.87728>
    <7.11106, 5.75306>
    <7.12667, 5.62862>
    <7.14101, 5.50401>
    <7.15418, 5.37925>
    <7.166, 5.25435>
    <7.17695, 5.12935>
    <7.18648, 5.00422>
    <7.19528, 4.87903>
    <7.20272, 4.75374>
    <7.20944, 4.6284>
    <7.21507, 4.503>
    <7.21987, 4.37757>
    <7.22378, 4.2521>
    <7.22674, 4.12659>
    <7.22899, 4.00108>
    <7.23018, 3.87554>
    <7.23084, 3.75>
    <7.23018, 3.62446>
    <7.22899, 3.49892>
    <7.22674, 3.37341>
    <7.22378, 3.2479>
    <7.21987, 3.12243>
    <7.21507, 2.997>
    <7.20944, 2.8716>
    <7.20272, 2.74626>
    <7.19528, 2.62097>
    <7.18648, 2.49578>
    <7.17695, 2.37065>
    <7.166, 2.24565>
    <7.15418, 2.12075>
    <7.14101, 1.99599>
    <7.12667, 1.87138>
    <7.11106, 1.74694>
    <7.094, 1.62272>
    <7.07555, 1.49872>
    <7.05545, 1.375>
    <7.03375, 1.25159>
    <7.01019, 1.12856>
    <6.9851, 1.00588>
    <6.95727, 0.883818>
    <6.92763, 0.762296>
    <6.89521, 0.641421>
    <6.85993, 0.521726>
    <6.82309, 0.402297>
    <6.78118, 0.284853>
    <6.73073, 0.17074>
    <6.6593, 0.0696338>
    <6.56318, 0>
    texture { Barrel } }
  matrix <0.999819, 0, -0.000156078, 0, 1, 0, -0.000156078, 0, 1.00018, 3.01828, 0, -0.752021>
}
plane { y, 0 texture { Fixture } }
