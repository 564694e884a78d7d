// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 54.614944, 0.000000>
  direction <0.000000, -2740.322289, 0.000000>
  right <1456.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 1088.000000> }
light_source { <16.533749, 47.125229, -2.542223> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <16.138346, 47.125229, 4.402445> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <12.952477, 47.125229, 10.585890> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <7.527007, 47.125229, 14.938939> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <0.800049, 47.125229, 16.708910> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <-6.065245, 47.125229, 15.589758> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <-11.881802, 47.125229, 11.774995> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <-15.643889, 47.125229, 5.924229> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <-16.701005, 47.125229, -0.950890> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <-14.870365, 47.125229, -7.661592> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <-10.468504, 47.125229, -13.047535> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <-4.256544, 47.125229, -16.177440> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <2.691411, 47.125229, -16.510120> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <9.173997, 47.125229, -13.988049> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
light_source { <14.070316, 47.125229, -9.047318> rgb 0.133333 fade_distance 47.2065 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { bumps 0.0692944 scale <0.125162, 0.0181887, 0.0181887> rotate y * 86.5893 translate <-8.742531, -0.658680, -19.518204> }
  finish { ambient 0 emission 0 diffuse 0.695382 specular 0.256054 roughness 0.0344574 metallic reflection { 0.0504873 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { onion 0.564111 scallop_wave scale 0.180187 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.291636 specular 0.0536578 roughness 0.0578022 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.800000, 0.680000, 0.420000> }
  normal { gradient y 0.31067 sine_wave scale 0.0996586 translate <-8.742531, -0.658680, -19.518204> }
  finish { ambient 0 emission 0 diffuse 0.3418 specular 0.113736 roughness 0.0895236 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.044320, 0.044320, 0.043628> }
  normal { bumps 0.29483 scale 0.160435 translate <-8.742531, -0.658680, -19.518204> }
  finish { ambient 0 emission 0 diffuse 0.85871 specular 0.149336 roughness 0.132807 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.99966 * (1 + 0.00453544 * cos(2 * atan2(z, x) + 0.469261) + 0.00488993 * cos(3 * atan2(z, x) + 3.69861)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.47217
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.47217, 7.5>
    <6.58137, 7.45421>
    <6.65892, 7.35792>
    <6.71511, 7.24571>
    <6.76519, 7.12994>
    <6.80946, 7.01162>
    <6.85368, 6.89314>
    <6.89172, 6.77233>
    <6.92847, 6.65104>
    <6.96186, 6.52864>
    <6.99265, 6.40545>
    <7.02148, 6.28173>
    <7.04816, 6.15745>
    <7.07291, 6.03272>
    <7.09568, 5.90755>
    <7.11675, 5.78204>
    <7.13596, 5.65619>
    <7.15374, 5.53009>
    <7.16994, 5.40375>
    <7.1847, 5.2772>
    <7.19821, 5.15049>
    <7.21019, 5.0236>
    <7.22116, 4.8966>
    <7.23047, 4.76945>
    <7.23884, 4.64222>
    <7.24585, 4.5149>
    <7.25186, 4.38752>
    <7.2567, 4.26008>
    <7.26045, 4.1326>
    <7.26321, 4.00508>
    <7.26475, 3.87755>
    <7.26553, 3.75>
    <7.26475, 3.62245>
    <7.26321, 3.49492>
    <7.26045, 3.3674>
    <7.2567, 3.23992>
    <7.25186, 3.11248>
    <7.24585, 2.9851>
    <7.23884, 2.85778>
    <7.23047, 2.73055>
    <7.22116, 2.6034>
    <7.21019, 2.4764>
    <7.19821, 2.34951>
    <7.1847, 2.2228>
    <7.16994, 2.09625>
    <7.15374, 1.96991>
    <7.13596, 1.84381>
    <7.11675, 1.71796>
    <7.09568, 1.59245>
    <7.07291, 1.46728>
    <7.04816, 1.34255>
    <7.02148, 1.21827>
    <6.99265, 1.09455>
    <6.96186, 0.971365>
    <6.92847, 0.848963>
    <6.89172, 0.727673>
    <6.85368, 0.60686>
    <6.80946, 0.488378>
    <6.76519, 0.37006>
    <6.71511, 0.254291>
    <6.65892, 0.142079>
    <6.58137, 0.0457946>
    <6.47217, 0>
    texture { Barrel } }
  matrix <0.997771, 0, -0.00507008, 0, 1, 0, -0.00507008, 0, 1.00226, -2.81264, 0, 0.852237>
}
plane { y, 0 texture { Fixture } }
