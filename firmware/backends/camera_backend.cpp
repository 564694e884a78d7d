#include "firmware/backends/camera_backend.h"

#include <filesystem>

#include "firmware/backends/backend_config.h"
#include "hal/file/file_camera.h"
#ifdef ICACAM_HAVE_V4L2
#include "hal/v4l2/v4l2_camera.h"
#endif
#ifdef ICACAM_HAVE_LIBCAMERA
#include "hal/libcamera/libcamera_camera.h"
#endif

namespace icacam::fw {

namespace {

using CameraResult = hal::Result<std::unique_ptr<hal::Camera>>;

#ifdef ICACAM_HAVE_V4L2
constexpr bool kV4l2 = true;
// A UVC camera: camera.device, else the udev rule's /dev/icacam-camera (deploy/), else the
// first one.
std::unique_ptr<hal::Camera> makeV4l2(const Config &cfg, hal::Clock &clock, const hal::CameraControls &asked)
{
    const std::string videoNode = !cfg.cameraDevice.empty()                       ? cfg.cameraDevice
                                  : std::filesystem::exists("/dev/icacam-camera") ? "/dev/icacam-camera"
                                                                                  : "/dev/video0";
    return std::make_unique<hal::V4l2Camera>(
        clock,
        hal::V4l2Options{videoNode, 4, asked, cfg.cameraWidth, cfg.cameraHeight, cfg.stampDelayUs, cfg.whiteBalanceK});
}
#else
constexpr bool kV4l2 = false;
std::unique_ptr<hal::Camera> makeV4l2(const Config &, hal::Clock &, const hal::CameraControls &)
{
    return nullptr;
}
#endif

#ifdef ICACAM_HAVE_LIBCAMERA
constexpr bool kLibcamera = true;
// A CSI camera: fixed exposure and gain, locked colour gains; unset ones keep the
// LibcameraOptions defaults (auto-exposure and AWB stay off either way).
std::unique_ptr<hal::Camera> makeLibcamera(const Config &cfg, hal::Clock &clock, const hal::CameraControls &asked)
{
    hal::LibcameraOptions csi;
    csi.camera = cfg.cameraId;
    csi.width = cfg.cameraWidth;
    csi.height = cfg.cameraHeight;
    csi.toneGamma = cfg.toneGamma;
    csi.tuning = cfg.cameraTuning.empty() || cfg.cameraTuning == "system" ? cfg.cameraTuning
                                                                          : pathFromConfig(cfg, cfg.cameraTuning);
    if (asked.exposureUs >= 0) csi.controls.exposureUs = asked.exposureUs;
    if (asked.analogueGain >= 0) csi.controls.analogueGain = asked.analogueGain;
    if (asked.redGain >= 0) csi.controls.redGain = asked.redGain, csi.controls.blueGain = asked.blueGain;
    csi.controls.lensPosition = asked.lensPosition;
    csi.controls.sharpness = asked.sharpness;
    csi.controls.noiseReduction = asked.noiseReduction;
    return std::make_unique<hal::LibcameraCamera>(clock, csi);
}
#else
constexpr bool kLibcamera = false;
std::unique_ptr<hal::Camera> makeLibcamera(const Config &, hal::Clock &, const hal::CameraControls &)
{
    return nullptr;
}
#endif

} // namespace

std::string cameraBackendIssue(const Config &cfg)
{
    const std::string &b = cfg.cameraBackend;
    if (b == "file" || (kV4l2 && b == "v4l2") || (kLibcamera && b == "libcamera")) return "";
    return notBuiltIssue("camera.backend", b, "file");
}

hal::Result<std::unique_ptr<hal::Camera>> makeCamera(const Config &cfg, hal::Clock &clock,
                                                     const hal::ScriptedLight *light)
{
    // Imaging controls as configured; the file camera reports them back with each frame.
    const hal::CameraControls asked = cameraControlsOf(cfg);
    const std::string &b = cfg.cameraBackend;
    if (b == "file")
        return {std::make_unique<hal::FileCamera>(clock, hal::FileCameraOptions{pathFromConfig(cfg, cfg.cameraFrames),
                                                                                cfg.cameraStrideAlign,
                                                                                cfg.cameraLoop != 0, 0, asked, light}),
                {}};
    if (kV4l2 && b == "v4l2") return {makeV4l2(cfg, clock, asked), {}};
    if (kLibcamera && b == "libcamera") return {makeLibcamera(cfg, clock, asked), {}};
    return CameraResult::fail(hal::Errc::Invalid, cameraBackendIssue(cfg));
}

} // namespace icacam::fw
