// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 61.799429, 0.000000>
  direction <0.000000, -1469.879756, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <12.727413, 54.657140, 19.897477> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <4.680162, 54.657140, 23.151517> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <-3.999172, 54.657140, 23.278816> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <-12.138395, 54.657140, 20.262182> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <-18.638261, 54.657140, 14.509028> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <-22.620926, 54.657140, 6.796349> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <-23.548510, 54.657140, -1.834214> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <-21.295737, 54.657140, -10.217056> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <-16.166857, 54.657140, -17.220029> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <-8.854553, 54.657140, -21.897341> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <-0.346393, 54.657140, -23.617296> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <8.208550, 54.657140, -22.147604> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <15.654882, 54.657140, -17.686756> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <20.986936, 54.657140, -10.837213> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <23.484587, 54.657140, -2.524044> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <22.810516, 54.657140, 6.130010> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
light_source { <19.055757, 54.657140, 13.956173> rgb 0.117647 fade_distance 54.3963 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { bumps 0.116248 scale <0.275131, 0.0157381, 0.0157381> rotate y * 139.199 translate <-7.159255, -37.752684, -27.854987> }
  finish { ambient 0 emission 0 diffuse 0.456514 specular 0.178317 roughness 0.0346774 metallic reflection { 0.06929 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { onion 0.485945 scallop_wave scale 0.0914345 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.0512683 specular 0.788594 roughness 0.0130583 metallic reflection { 0.426731 metallic } }
}
#declare Barrel = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { gradient y 0.189953 sine_wave scale 0.0527305 translate <-7.159255, -37.752684, -27.854987> }
  finish { ambient 0 emission 0 diffuse 0.853074 specular 0.221259 roughness 0.109383 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.061204, 0.061204, 0.061118> }
  normal { bumps 0.165451 scale 0.213351 translate <-7.159255, -37.752684, -27.854987> }
  finish { ambient 0 emission 0 diffuse 0.629061 specular 0.102632 roughness 0.0948691 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.93994 * (1 + 0.00450815 * cos(2 * atan2(z, x) + 2.82586) + 0.00592647 * cos(3 * atan2(z, x) + 6.26491)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.46604
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.46604, 7.5>
    <6.56616, 7.43081>
    <6.63786, 7.32835>
    <6.69235, 7.21518>
    <6.7376, 7.09764>
    <6.78279, 6.98035>
    <6.82437, 6.86145>
    <6.8645, 6.74202>
    <6.90241, 6.62179>
    <6.93787, 6.50073>
    <6.97164, 6.37916>
    <7.0035, 6.25701>
    <7.03335, 6.13431>
    <7.06149, 6.01117>
    <7.08796, 5.88763>
    <7.11269, 5.76369>
    <7.13568, 5.63938>
    <7.15728, 5.51479>
    <7.17686, 5.38983>
    <7.19505, 5.26465>
    <7.21156, 5.1392>
    <7.22658, 5.01355>
    <7.2402, 4.88772>
    <7.25216, 4.7617>
    <7.26294, 4.63557>
    <7.27186, 4.50927>
    <7.27959, 4.38289>
    <7.28573, 4.25641>
    <7.29059, 4.12986>
    <7.29412, 4.00327>
    <7.29616, 3.87664>
    <7.29716, 3.75>
    <7.29616, 3.62336>
    <7.29412, 3.49673>
    <7.29059, 3.37014>
    <7.28573, 3.24359>
    <7.27959, 3.11711>
    <7.27186, 2.99073>
    <7.26294, 2.86443>
    <7.25216, 2.7383>
    <7.2402, 2.61228>
    <7.22658, 2.48645>
    <7.21156, 2.3608>
    <7.19505, 2.23535>
    <7.17686, 2.11017>
    <7.15728, 1.98521>
    <7.13568, 1.86062>
    <7.11269, 1.73631>
    <7.08796, 1.61237>
    <7.06149, 1.48883>
    <7.03335, 1.36569>
    <7.0035, 1.24299>
    <6.97164, 1.12084>
    <6.93787, 0.999269>
    <6.90241, 0.87821>
    <6.8645, 0.757985>
    <6.82437, 0.63855>
    <6.78279, 0.519647>
    <6.7376, 0.40236>
    <6.69235, 0.284824>
    <6.63786, 0.171646>
    <6.56616, 0.0691908>
    <6.46604, 0>
    texture { Barrel } }
  matrix <0.996495, 0, -0.00477557, 0, 1, 0, -0.00477557, 0, 1.00354, -3.23307, 0, 0.267639>
}
plane { y, 0 texture { Fixture } }
