#include "calibration/calibration_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace icacam::calibration {

namespace {

constexpr const char *kFormat = "icacam-calibration-1";

std::string trim(const std::string &s)
{
    const size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// A whole word as a finite number (strtod, nothing left over).
bool parseNumber(const std::string &s, double *out)
{
    if (s.empty() || s.size() > 64) return false;
    char *end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v)) return false;
    *out = v;
    return true;
}

std::string numbers(const double *v, int n)
{
    std::string s;
    char buf[40];
    for (int i = 0; i < n; ++i) {
        std::snprintf(buf, sizeof buf, "%s%.17g", i ? " " : "", v[i]);
        s += buf;
    }
    return s;
}

} // namespace

std::string writeCalibrationFile(const std::string &path, const CalibrationFile &c)
{
    std::ofstream f(path);
    if (!f) return "cannot write '" + path + "'";
    const vision::PlaneCalibration &p = c.plane;
    const double size[2] = {double(c.imageWidth), double(c.imageHeight)};
    const double k[5] = {p.k1, p.k2, p.p1, p.p2, p.k3};
    f << "# icacam camera calibration (docs/calibration.md). Pixels → mm in a plane parallel\n"
      << "# to the fixture; the height of that plane comes from each specimen.\n"
      << "format = " << kFormat << "\n"
      << "image_size = " << numbers(size, 2) << "\n"
      << "fx = " << numbers(&p.fx, 1) << "\n"
      << "fy = " << numbers(&p.fy, 1) << "\n"
      << "cx = " << numbers(&p.cx, 1) << "\n"
      << "cy = " << numbers(&p.cy, 1) << "\n"
      << "# OpenCV order: k1 k2 p1 p2 k3\n"
      << "distortion = " << numbers(k, 5) << "\n"
      << "# X_camera = R · X_fixture + t; R row-major, t in mm\n"
      << "fixture_rotation = " << numbers(p.r, 9) << "\n"
      << "fixture_translation_mm = " << numbers(p.t, 3) << "\n"
      << "rms_px = " << numbers(&c.rmsPx, 1) << "\n"
      << "views = " << c.views << "\n"
      << "board = " << c.board << "\n"
      << "board_thickness_mm = " << numbers(&c.boardThicknessMm, 1) << "\n";
    f.close();
    if (!f) return "cannot write '" + path + "'";
    return "";
}

std::string parseCalibrationText(const std::string &text, CalibrationFile *out)
{
    CalibrationFile c;
    std::map<std::string, std::pair<int, std::string>> kv;
    std::istringstream in(text);
    std::string line;
    for (int no = 1; std::getline(in, line); ++no) {
        const size_t hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        line = trim(line);
        if (line.empty()) continue;
        const size_t eq = line.find('=');
        if (eq == std::string::npos) return "line " + std::to_string(no) + ": expected 'key = value'";
        const std::string key = trim(line.substr(0, eq));
        if (kv.count(key)) return "line " + std::to_string(no) + ": '" + key + "' given twice";
        kv[key] = {no, trim(line.substr(eq + 1))};
    }
    auto list = [&](const char *key, int n, double *dst, bool required) -> std::string {
        auto it = kv.find(key);
        if (it == kv.end()) return required ? std::string("missing '") + key + "'" : "";
        std::istringstream v(it->second.second);
        std::vector<double> vals;
        std::string word;
        while (v >> word) {
            double d;
            if (!parseNumber(word, &d))
                return "line " + std::to_string(it->second.first) + ": bad number '" + word + "' in " + key;
            vals.push_back(d);
        }
        if (int(vals.size()) != n)
            return "line " + std::to_string(it->second.first) + ": " + key + " needs " + std::to_string(n) + " number" +
                   (n > 1 ? "s" : "");
        std::copy(vals.begin(), vals.end(), dst);
        return "";
    };
    auto fmt = kv.find("format");
    if (fmt == kv.end()) return "missing 'format' (not an icacam calibration file?)";
    if (fmt->second.second != kFormat)
        return "unknown format '" + fmt->second.second + "' (this icacam reads " + kFormat + ")";
    vision::PlaneCalibration &p = c.plane;
    double size[2], k[5], views = 0;
    for (std::string e : {list("image_size", 2, size, true), list("fx", 1, &p.fx, true), list("fy", 1, &p.fy, true),
                          list("cx", 1, &p.cx, true), list("cy", 1, &p.cy, true), list("distortion", 5, k, true),
                          list("fixture_rotation", 9, p.r, true), list("fixture_translation_mm", 3, p.t, true),
                          list("rms_px", 1, &c.rmsPx, false), list("views", 1, &views, false),
                          list("board_thickness_mm", 1, &c.boardThicknessMm, false)})
        if (!e.empty()) return e;
    p.k1 = k[0], p.k2 = k[1], p.p1 = k[2], p.p2 = k[3], p.k3 = k[4];
    if (!(size[0] >= 1 && size[1] >= 1 && size[0] <= 65535 && size[1] <= 65535))
        return "image_size must be two positive whole numbers";
    c.imageWidth = int(size[0]), c.imageHeight = int(size[1]);
    c.views = int(views);
    if (auto b = kv.find("board"); b != kv.end()) c.board = b->second.second;
    if (!p.valid()) return "the camera or fixture pose is not physical (focal length, rotation or distance)";
    *out = c;
    return "";
}

std::string readCalibrationFile(const std::string &path, CalibrationFile *out)
{
    std::ifstream f(path);
    if (!f) return "cannot read calibration '" + path + "'";
    std::stringstream ss;
    ss << f.rdbuf();
    const std::string e = parseCalibrationText(ss.str(), out);
    return e.empty() ? "" : "calibration '" + path + "': " + e;
}

} // namespace icacam::calibration
