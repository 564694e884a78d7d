// icacam photographic bench: one upset specimen under a ring light (host_tools/photo).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }
background { rgb 0 }
camera { perspective location <0.000000, 99.973250, 0.000000>
  direction <0.000000, -2520.318239, 0.000000>
  right <640.000000, 0.000000, 0.000000>
  up <0.000000, 0.000000, 480.000000> }
light_source { <-0.337647, 95.433089, -22.147037> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <4.972297, 95.433089, -21.584288> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <9.993270, 95.433089, -19.767140> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <14.433469, 95.433089, -16.801197> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <18.034849, 95.433089, -12.858829> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <20.588108, 95.433089, -8.169153> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <21.944861, 95.433089, -3.004716> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <22.026259, 95.433089, 2.334345> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <20.827571, 95.433089, 7.537742> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <18.418459, 95.433089, 12.303073> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <14.938934, 95.433089, 16.353394> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <10.591213, 95.433089, 19.453315> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <5.627969, 95.433089, 21.422680> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <0.337647, 95.433089, 22.147037> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-4.972297, 95.433089, 21.584288> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-9.993270, 95.433089, 19.767140> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-14.433469, 95.433089, 16.801197> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-18.034849, 95.433089, 12.858829> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-20.588108, 95.433089, 8.169153> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-21.944861, 95.433089, 3.004716> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-22.026259, 95.433089, -2.334345> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-20.827571, 95.433089, -7.537742> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-18.418459, 95.433089, -12.303073> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-14.938934, 95.433089, -16.353394> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-10.591213, 95.433089, -19.453315> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
light_source { <-5.627969, 95.433089, -21.422680> rgb 0.0769231 fade_distance 92.4885 fade_power 2 }
#declare FaceClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { bumps 0.0661151 scale <0.123844, 0.021178, 0.021178> rotate y * 45.577 translate <-18.404187, 6.881423, -23.056267> }
  finish { ambient 0 emission 0 diffuse 0.773065 specular 0.418216 roughness 0.0715756 metallic reflection { 0.0498735 metallic } }
}
#declare RingClean = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { onion 1.10251 scallop_wave scale 0.159223 translate <0, 7.5, 0> }
  finish { ambient 0 emission 0 diffuse 0.380234 specular 0.152803 roughness 0.059057 metallic }
}
#declare Barrel = texture {
  pigment { rgb <0.820000, 0.520000, 0.380000> }
  normal { gradient y 0.370471 sine_wave scale 0.107157 translate <-18.404187, 6.881423, -23.056267> }
  finish { ambient 0 emission 0 diffuse 0.40455 specular 0.148403 roughness 0.0568378 metallic }
}
#declare Stain = texture {
  pigment { rgb <0.700000, 0.700000, 0.700000> }
  finish { ambient 0 emission 0 diffuse 0.5 specular 0.2 roughness 0.05 metallic }
}
#declare Face = texture { FaceClean }
#declare Ring = texture { RingClean }
#declare Fixture = texture {
  pigment { rgb <0.053411, 0.053411, 0.053300> }
  normal { bumps 0.131582 scale 0.125937 translate <-18.404187, 6.881423, -23.056267> }
  finish { ambient 0 emission 0 diffuse 0.636819 specular 0.0318186 roughness 0.174142 metallic }
}
#declare InnerEdge = function(x, y, z) { select(sqrt(x * x + z * z) - 5.96181 * (1 + 0.00401164 * cos(2 * atan2(z, x) + 1.55119) + 0.00402665 * cos(3 * atan2(z, x) + 5.12765)), 0, 1) }
union {
  disc { <0, 7.5, 0>, y, 6.46989
    texture { function { InnerEdge(x, y, z) } texture_map { [0 Face] [0.5 Face] [0.5 Ring] [1 Ring] } } }
  lathe { linear_spline 63
    <6.46989, 7.5>
    <6.57276, 7.43928>
    <6.64603, 7.3386>
    <6.70113, 7.22576>
    <6.74701, 7.10841>
    <6.79204, 6.99086>
    <6.83391, 6.87191>
    <6.87328, 6.75199>
    <6.91065, 6.63138>
    <6.94531, 6.50984>
    <6.97813, 6.38776>
    <7.00902, 6.2651>
    <7.03783, 6.14187>
    <7.0649, 6.01821>
    <7.09025, 5.89414>
    <7.1139, 5.7697>
    <7.13578, 5.64489>
    <7.15631, 5.51983>
    <7.17487, 5.39442>
    <7.19205, 5.26879>
    <7.20767, 5.14293>
    <7.22181, 5.01687>
    <7.23467, 4.89066>
    <7.24587, 4.76428>
    <7.25597, 4.63778>
    <7.26432, 4.51114>
    <7.27154, 4.38443>
    <7.27731, 4.25763>
    <7.28185, 4.13077>
    <7.28516, 4.00388>
    <7.28705, 3.87695>
    <7.28799, 3.75>
    <7.28705, 3.62305>
    <7.28516, 3.49612>
    <7.28185, 3.36923>
    <7.27731, 3.24237>
    <7.27154, 3.11557>
    <7.26432, 2.98886>
    <7.25597, 2.86222>
    <7.24587, 2.73572>
    <7.23467, 2.60934>
    <7.22181, 2.48313>
    <7.20767, 2.35707>
    <7.19205, 2.23121>
    <7.17487, 2.10558>
    <7.15631, 1.98017>
    <7.13578, 1.85511>
    <7.1139, 1.7303>
    <7.09025, 1.60586>
    <7.0649, 1.48179>
    <7.03783, 1.35813>
    <7.00902, 1.2349>
    <6.97813, 1.11224>
    <6.94531, 0.990156>
    <6.91065, 0.868618>
    <6.87328, 0.748007>
    <6.83391, 0.628094>
    <6.79204, 0.509143>
    <6.74701, 0.391594>
    <6.70113, 0.274238>
    <6.64603, 0.161397>
    <6.57276, 0.0607244>
    <6.46989, 0>
    texture { Barrel } }
  matrix <1.00441, 0, 0.000903153, 0, 1, 0, 0.000903153, 0, 0.995611, -1.64683, 0, -0.316791>
}
plane { y, 0 texture { Fixture } }
