#pragma once
// A V4L2 capture device (a USB UVC camera) behind the Camera seam: the mode chosen from
// the formats, sizes and frame intervals the device lists (hal/v4l2/stream_mode.h: 15 fps or
// more preferred, then the largest area within the configured maximum, or the size
// configured), streamed at its fastest interval; GREY / NV12 / YUYV viewed in place by
// vision::lumaOf or MJPEG decoded to luma (libjpeg-turbo), imaging controls set through
// VIDIOC_S_EXT_CTRLS and read back, white balance fixed, mmap streaming with buffers
// allocated once in configure(), dequeue with a poll timeout, only frames exposed after the
// LED settled handed out (fresh_frame.h), their timestamps believed as far as the buffer
// flags and the driver allow (hal/v4l2/buffer_stamp.h), and recovery after an unplug:
// capture() reports Errc::Closed once, then reopens the device on the next call.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "hal/camera.h"
#include "hal/clock.h"
#include "hal/unique_fd.h"
#include "hal/v4l2/buffer_stamp.h"
#include "hal/v4l2/stream_mode.h"

namespace icacam::hal {

// How driver buffers reach this process. The real one mmaps them; a test supplies its own
// memory (umockdev does not wrap mmap, PLATFORM.md).
class V4l2BufferMapper {
public:
    virtual ~V4l2BufferMapper() = default;
    virtual void *map(int fd, size_t length, uint32_t offset) = 0; // nullptr on failure
    virtual void unmap(void *addr, size_t length) = 0;
};

struct V4l2Options {
    std::string device = "/dev/video0";
    int bufferCount = 4;
    // Exposure (100 µs steps on UVC), gain, red/blue balance, focus and sharpness in the
    // device's own units (`v4l2-ctl -L` lists them); -1 leaves a control as it is.
    CameraControls controls;
    int width = 0, height = 0; // 0 × 0: the largest listed size within the maximum
    // Most time from the end of a frame's exposure to its buffer timestamp (uvcvideo: the
    // first USB packet); -1: one frame interval, which covers readout and MJPEG encoding.
    int stampDelayUs = -1;
    // White balance fixed at this colour temperature (kelvin; auto white balance off) when
    // the camera has the control and red/blue gains are not set; -1 leaves it as it is.
    // 5000 K is a white LED ring's neighbourhood; luma moves with the balance, through the
    // colour matrix, so an auto balance moves the grey levels from shot to shot.
    int whiteBalanceK = 5000;
};

class V4l2Camera final : public Camera {
public:
    static constexpr int kMaxBuffers = 8;

    // mapper: nullptr for mmap(2).
    V4l2Camera(const Clock &clock, V4l2Options options, V4l2BufferMapper *mapper = nullptr);
    ~V4l2Camera() override;
    V4l2Camera(const V4l2Camera &) = delete;
    V4l2Camera &operator=(const V4l2Camera &) = delete;

    Error configure(const CameraFormat &fmt) override;
    using Camera::capture;
    Error capture(const CaptureRequest &req, CapturedFrame *out) override;
    std::string describe() const override { return description_; }
    Error setStampDelayUs(int us) override;
    // VIDIOC_S_EXT_CTRLS on the streaming device, each value within the range QUERYCTRL gives
    // and its automatic control off first: exposure_absolute (exposure_auto manual),
    // gain (else analogue_gain), red/blue_balance, focus_absolute (focus_automatic_continuous
    // off), sharpness, in the device's own units; read back. The next capture() refuses frames
    // exposed before the change and one frame interval after it. No noise reduction control.
    Result<CameraControls> setControls(const CameraControls &asked) override;
    // Continuous autofocus on, frames until focus_absolute has held still for a while, then
    // that position held as setControls() holds it (UVC has no one-shot focus).
    Result<double> focusOnce(int timeoutMs) override;

    // What the driver agreed to (valid after configure()).
    PixelFormat format() const { return format_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int stride() const { return stride_; }
    bool mjpeg() const { return mjpeg_; }
    int64_t frameIntervalUs() const { return frameIntervalUs_; }
    const V4l2Mode &mode() const { return mode_; }
    // What the buffer timestamps are taken to mean (from the flags QUERYBUF reports).
    const BufferStampModel &stampModel() const { return stampModel_; }
    int whiteBalanceK() const { return whiteBalanceReadK_; } // read back; -1 not fixed
    const CameraControls &reported() const { return reported_; }

private:
    struct Buffer {
        void *addr = nullptr;
        size_t length = 0;
    };
    Error openAndStart();
    Error negotiate();
    void applyControls();
    void stop(); // stream off, unmap, close; safe to call twice
    Error requeueHeld();

    const Clock &clock_;
    V4l2Options options_;
    V4l2BufferMapper *mapper_;
    CameraFormat wanted_{};
    bool configured_ = false;
    UniqueFd fd_;
    Buffer buffers_[kMaxBuffers];
    int bufferCount_ = 0;
    int held_ = -1; // index of the buffer handed out by the last capture()
    bool streaming_ = false;
    PixelFormat format_ = PixelFormat::Grey8;
    int width_ = 0, height_ = 0, stride_ = 0;
    size_t imageBytes_ = 0;
    bool mjpeg_ = false;
    std::unique_ptr<uint8_t[]> decoded_; // MJPEG frames' luma, sized in configure()
    size_t decodedBytes_ = 0;
    int64_t frameIntervalUs_ = 33333;
    V4l2Mode mode_;               // as chosen from the list (its interval: the one asked)
    std::string driver_;          // QUERYCAP's driver name: "uvcvideo"
    BufferStampModel stampModel_; // from the buffers' flags
    int whiteBalanceReadK_ = -1;
    CameraControls reported_; // read back after setting
    std::string description_ = "v4l2: not opened";
    std::string refused_;           // controls the device did not take
    int64_t controlsChangedNs_ = 0; // frames exposed before this are from the controls before setControls()
};

} // namespace icacam::hal
