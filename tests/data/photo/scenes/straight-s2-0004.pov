// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 97.092414, 0.000000>
  direction <0.000000, -2489.592055, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-5.118869, 89.235414, -14.482200> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <2.808030, 89.235414, -15.101387> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <9.982519, 89.235414, -11.674170> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <14.482200, 89.235414, -5.118869> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <15.101387, 89.235414, 2.808030> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <11.674170, 89.235414, 9.982519> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <5.118869, 89.235414, 14.482200> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <-2.808030, 89.235414, 15.101387> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <-9.982519, 89.235414, 11.674170> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <-14.482200, 89.235414, 5.118869> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <-15.101387, 89.235414, -2.808030> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
light_source { <-11.674170, 89.235414, -9.982519> rgb 0.166667 fade_distance 89.5948 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { bumps 0.0382281 scale <0.322723, 0.0198938, 0.0198938> rotate y * 38.3942 translate <-18.176042, 2.924257, 3.214967> }
  finish { ambient 0 emission 0 diffuse 0.812784 specular 0.323334 roughness 0.0414985 metallic reflection { 0.0865552 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { onion 0.686401 scallop_wave scale 0.172037 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.257376 specular 0.0500771 roughness 0.0639694 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.600000, 0.610000, 0.630000> }
  normal { gradient y 0.399532 sine_wave scale 0.102989 translate <-18.176042, 2.924257, 3.214967> }
  finish { ambient 0 emission 0 diffuse 0.265541 specular 0.119069 roughness 0.0879672 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.067931, 0.067931, 0.069424> }
  normal { bumps 0.107892 scale 0.146642 translate <-18.176042, 2.924257, 3.214967> }
  finish { ambient 0 emission 0 diffuse 0.672446 specular 0.137271 roughness 0.147824 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 6.17847 * (1 + 0.0118188 * cos(2 * atan2(z, x) + 0.573498) + 0.00510216 * cos(3 * atan2(z, x) + 2.33995)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.55092
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.55092, 7.5>
    <6.64103, 7.42613>
    <6.70639, 7.32211>
    <6.75422, 7.2073>
    <6.79272, 7.08849>
    <6.82784, 6.96864>
    <6.86287, 6.84867>
    <6.89631, 6.7282>
    <6.92841, 6.60732>
    <6.95886, 6.48596>
    <6.98763, 6.36415>
    <7.0151, 6.24199>
    <7.04099, 6.11945>
    <7.06548, 5.99658>
    <7.08848, 5.87339>
    <7.11011, 5.74991>
    <7.13024, 5.62615>
    <7.14917, 5.50217>
    <7.16656, 5.37793>
    <7.18263, 5.25348>
    <7.19733, 5.12884>
    <7.21066, 5.00402>
    <7.22284, 4.87906>
    <7.23344, 4.75394>
    <7.24303, 4.62872>
    <7.25105, 4.50337>
    <7.25796, 4.37794>
    <7.26349, 4.25244>
    <7.26784, 4.12688>
    <7.27102, 4.00128>
    <7.27284, 3.87565>
    <7.27375, 3.75>
    <7.27284, 3.62435>
    <7.27102, 3.49872>
    <7.26784, 3.37312>
    <7.26349, 3.24756>
    <7.25796, 3.12206>
    <7.25105, 2.99663>
    <7.24303, 2.87128>
    <7.23344, 2.74606>
    <7.22284, 2.62094>
    <7.21066, 2.49598>
    <7.19733, 2.37116>
    <7.18263, 2.24652>
    <7.16656, 2.12207>
    <7.14917, 1.99783>
    <7.13024, 1.87385>
    <7.11011, 1.75009>
    <7.08848, 1.62661>
    <7.06548, 1.50342>
    <7.04099, 1.38055>
    <7.0151, 1.25801>
    <6.98763, 1.13585>
    <6.95886, 1.01404>
    <6.92841, 0.892678>
    <6.89631, 0.771798>
    <6.86287, 0.651332>
    <6.82784, 0.531356>
    <6.79272, 0.411507>
    <6.75422, 0.292704>
    <6.70639, 0.177891>
    <6.64103, 0.0738656>
    <6.55092, 0>
    texture { Barrel } }
  matrix <1.00342, 0, -0.00204406, 0, 1, 0, -0.00204406, 0, 0.996597, -0.628226, 0, -0.187061>
}
plane { y, 0 texture { Fixture } }
