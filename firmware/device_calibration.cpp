#include "firmware/device_calibration.h"

namespace icacam::fw {

namespace {
std::string baseName(const std::string &p)
{
    const size_t slash = p.find_last_of('/');
    return slash == std::string::npos ? p : p.substr(slash + 1);
}
std::string size(int w, int h)
{
    return std::to_string(w) + "x" + std::to_string(h);
}
} // namespace

std::string loadDeviceCalibration(const Config &cfg, DeviceCalibration *out)
{
    *out = DeviceCalibration{};
    if (cfg.calibrationFile.empty()) return "";
    DeviceCalibration d;
    d.path = cfg.calibrationFile.front() == '/' || cfg.baseDir.empty() ? cfg.calibrationFile
                                                                       : cfg.baseDir + "/" + cfg.calibrationFile;
    d.name = baseName(d.path);
    if (std::string e = calibration::readCalibrationFile(d.path, &d.file); !e.empty()) return "calibration.file: " + e;
    if (d.file.imageWidth > cfg.cameraMaxWidth || d.file.imageHeight > cfg.cameraMaxHeight)
        return "calibration.file '" + d.path + "' is for " + size(d.file.imageWidth, d.file.imageHeight) +
               " images, larger than the camera's largest frame (camera.max_width x camera.max_height = " +
               size(cfg.cameraMaxWidth, cfg.cameraMaxHeight) + ")";
    d.present = true;
    *out = d;
    return "";
}

std::string frameSizeIssue(const DeviceCalibration &cal, int width, int height)
{
    if (!cal.present || (width == cal.file.imageWidth && height == cal.file.imageHeight)) return "";
    return "frame is " + size(width, height) + " but calibration '" + cal.name + "' is for " +
           size(cal.file.imageWidth, cal.file.imageHeight) + " images";
}

} // namespace icacam::fw
