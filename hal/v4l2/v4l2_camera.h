#pragma once
// A V4L2 capture device (a USB UVC camera) behind the Camera seam: format negotiation
// (GREY, NV12, YUYV: luma viewed in place by vision::lumaOf), mmap streaming with buffers
// allocated once in configure(), dequeue with a poll timeout, and recovery after an unplug:
// capture() reports Errc::Closed once, then reopens the device on the next call.
#include <cstddef>
#include <cstdint>
#include <string>

#include "hal/camera.h"
#include "hal/clock.h"
#include "hal/unique_fd.h"

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
    Error capture(int timeoutMs, CapturedFrame *out) override;

    // What the driver agreed to (valid after configure()).
    vision::PixelFormat format() const { return format_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int stride() const { return stride_; }

private:
    struct Buffer {
        void *addr = nullptr;
        size_t length = 0;
    };
    Error openAndStart();
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
    vision::PixelFormat format_ = vision::PixelFormat::Grey8;
    int width_ = 0, height_ = 0, stride_ = 0;
    size_t imageBytes_ = 0;
};

} // namespace icacam::hal
