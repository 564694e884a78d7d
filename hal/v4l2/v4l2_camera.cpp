// V4L2 streaming capture. The ioctl sequence is the kernel's documented one (Documentation/
// userspace-api/media/v4l/mmap.rst): QUERYCAP → S_FMT → REQBUFS → QUERYBUF + mmap per
// buffer → QBUF all → STREAMON; then DQBUF / QBUF per frame, STREAMOFF → munmap → REQBUFS 0.
#include "hal/v4l2/v4l2_camera.h"

#include <fcntl.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <time.h>

#include <cerrno>
#include <cstring>
#include <iterator>

namespace icacam::hal {

namespace {

int xioctl(int fd, unsigned long req, void *arg)
{
    int r;
    do {
        r = ::ioctl(fd, req, arg);
    } while (r < 0 && errno == EINTR);
    return r;
}

std::string sysError(const std::string &what) { return what + ": " + std::strerror(errno); }

// An unplugged UVC camera answers ENODEV; the chardev can also report EIO or hang up.
bool unplugged(int err) { return err == ENODEV || err == ENXIO || err == EIO; }

uint32_t fourcc(vision::PixelFormat f)
{
    switch (f) {
    case vision::PixelFormat::Grey8: return V4L2_PIX_FMT_GREY;
    case vision::PixelFormat::YUYV: return V4L2_PIX_FMT_YUYV;
    case vision::PixelFormat::NV12: return V4L2_PIX_FMT_NV12;
    default: return 0;
    }
}

bool fromFourcc(uint32_t cc, vision::PixelFormat *f)
{
    switch (cc) {
    case V4L2_PIX_FMT_GREY: *f = vision::PixelFormat::Grey8; return true;
    case V4L2_PIX_FMT_YUYV: *f = vision::PixelFormat::YUYV; return true;
    case V4L2_PIX_FMT_NV12: *f = vision::PixelFormat::NV12; return true;
    default: return false;
    }
}

int64_t monotonicNs()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

class MmapMapper final : public V4l2BufferMapper {
public:
    void *map(int fd, size_t length, uint32_t offset) override
    {
        void *p = ::mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_SHARED, fd, off_t(offset));
        return p == MAP_FAILED ? nullptr : p;
    }
    void unmap(void *addr, size_t length) override { ::munmap(addr, length); }
};
MmapMapper gMmap;

} // namespace

V4l2Camera::V4l2Camera(const Clock &clock, V4l2Options options, V4l2BufferMapper *mapper)
    : clock_(clock), options_(std::move(options)), mapper_(mapper ? mapper : &gMmap)
{
}

V4l2Camera::~V4l2Camera() { stop(); }

void V4l2Camera::stop()
{
    if (fd_.valid() && streaming_) {
        int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        (void)xioctl(fd_.get(), VIDIOC_STREAMOFF, &type);
    }
    streaming_ = false;
    for (int i = 0; i < bufferCount_; ++i) {
        if (buffers_[i].addr) mapper_->unmap(buffers_[i].addr, buffers_[i].length);
        buffers_[i] = {};
    }
    if (fd_.valid() && bufferCount_ > 0) {
        v4l2_requestbuffers rb{};
        rb.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        rb.memory = V4L2_MEMORY_MMAP;
        rb.count = 0; // frees the driver's buffers
        (void)xioctl(fd_.get(), VIDIOC_REQBUFS, &rb);
    }
    bufferCount_ = 0;
    held_ = -1;
    fd_.reset();
}

Error V4l2Camera::configure(const CameraFormat &fmt)
{
    if (fmt.maxWidth <= 0 || fmt.maxHeight <= 0)
        return Error::make(Errc::Invalid, "camera: maximum frame size must be positive");
    if (!fourcc(fmt.format))
        return Error::make(Errc::BadFormat, "camera: V4L2 delivers GREY, YUYV or NV12 only");
    if (options_.bufferCount < 2 || options_.bufferCount > kMaxBuffers)
        return Error::make(Errc::Invalid, "camera: buffer count must be 2…8");
    stop();
    wanted_ = fmt;
    configured_ = true;
    return openAndStart();
}

Error V4l2Camera::openAndStart()
{
    const std::string &dev = options_.device;
    fd_.reset(::open(dev.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC));
    if (!fd_.valid())
        return Error::make(errno == ENOENT ? Errc::NotFound : Errc::Io, sysError("camera " + dev));

    v4l2_capability cap{};
    if (xioctl(fd_.get(), VIDIOC_QUERYCAP, &cap) < 0) {
        const Error e = Error::make(Errc::Io, sysError("camera " + dev + ": not a V4L2 device"));
        stop();
        return e;
    }
    const uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || !(caps & V4L2_CAP_STREAMING)) {
        stop();
        return Error::make(Errc::BadFormat, "camera " + dev + ": no streaming video capture");
    }

    // Negotiation: the configured format first, then the other formats vision views in
    // place. The driver answers S_FMT with what it will do; accept only those formats and
    // sizes within the configured maximum.
    const vision::PixelFormat order[] = {wanted_.format, vision::PixelFormat::Grey8, vision::PixelFormat::NV12,
                                         vision::PixelFormat::YUYV};
    bool agreed = false;
    v4l2_format f{};
    for (size_t k = 0; k < std::size(order); ++k) {
        const vision::PixelFormat want = order[k];
        if (k > 0 && want == wanted_.format) continue; // asked for already
        f = {};
        f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        f.fmt.pix.width = uint32_t(wanted_.maxWidth);
        f.fmt.pix.height = uint32_t(wanted_.maxHeight);
        f.fmt.pix.pixelformat = fourcc(want);
        f.fmt.pix.field = V4L2_FIELD_NONE;
        if (xioctl(fd_.get(), VIDIOC_S_FMT, &f) < 0) {
            if (errno == EBUSY || unplugged(errno)) break;
            continue;
        }
        // Drivers adjust rather than refuse: any answer vision can view in place will do
        // (a UVC camera without GREY answers YUYV); MJPEG and the like mean "try the next".
        if (fromFourcc(f.fmt.pix.pixelformat, &format_)) {
            agreed = true;
            break;
        }
    }
    if (!agreed) {
        stop();
        return Error::make(Errc::BadFormat, "camera " + dev + ": none of GREY, NV12, YUYV accepted");
    }
    width_ = int(f.fmt.pix.width);
    height_ = int(f.fmt.pix.height);
    const int minStride = format_ == vision::PixelFormat::YUYV ? 2 * width_ : width_;
    stride_ = f.fmt.pix.bytesperline ? int(f.fmt.pix.bytesperline) : minStride;
    imageBytes_ = f.fmt.pix.sizeimage;
    if (width_ > wanted_.maxWidth || height_ > wanted_.maxHeight) {
        stop();
        return Error::make(Errc::TooLarge, "camera " + dev + ": driver chose " + std::to_string(width_) + "x" +
                                               std::to_string(height_) + ", above the configured maximum");
    }
    if (stride_ < minStride) {
        stop();
        return Error::make(Errc::BadStride, "camera " + dev + ": stride " + std::to_string(stride_) + " too short");
    }

    v4l2_requestbuffers rb{};
    rb.count = uint32_t(options_.bufferCount);
    rb.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    rb.memory = V4L2_MEMORY_MMAP;
    if (xioctl(fd_.get(), VIDIOC_REQBUFS, &rb) < 0 || rb.count < 2) {
        const Error e = Error::make(Errc::Io, sysError("camera " + dev + ": REQBUFS"));
        stop();
        return e;
    }
    bufferCount_ = int(rb.count < uint32_t(kMaxBuffers) ? rb.count : uint32_t(kMaxBuffers));
    for (int i = 0; i < bufferCount_; ++i) {
        v4l2_buffer b{};
        b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        b.memory = V4L2_MEMORY_MMAP;
        b.index = uint32_t(i);
        if (xioctl(fd_.get(), VIDIOC_QUERYBUF, &b) < 0) {
            const Error e = Error::make(Errc::Io, sysError("camera " + dev + ": QUERYBUF"));
            stop();
            return e;
        }
        buffers_[i].addr = mapper_->map(fd_.get(), b.length, b.m.offset);
        buffers_[i].length = b.length;
        if (!buffers_[i].addr) {
            const Error e = Error::make(Errc::Io, sysError("camera " + dev + ": mmap"));
            stop();
            return e;
        }
        if (xioctl(fd_.get(), VIDIOC_QBUF, &b) < 0) {
            const Error e = Error::make(Errc::Io, sysError("camera " + dev + ": QBUF"));
            stop();
            return e;
        }
    }
    int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (xioctl(fd_.get(), VIDIOC_STREAMON, &type) < 0) {
        const Error e = Error::make(Errc::Io, sysError("camera " + dev + ": STREAMON"));
        stop();
        return e;
    }
    streaming_ = true;
    return {};
}

Error V4l2Camera::requeueHeld()
{
    if (held_ < 0) return {};
    v4l2_buffer b{};
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    b.index = uint32_t(std::exchange(held_, -1));
    if (xioctl(fd_.get(), VIDIOC_QBUF, &b) < 0) return Error::make(Errc::Io, sysError("camera: QBUF"));
    return {};
}

Error V4l2Camera::capture(int timeoutMs, CapturedFrame *out)
{
    if (!configured_) return Error::make(Errc::Invalid, "camera: not configured");
    if (!streaming_) {
        // After an unplug: try the device again (the replugged camera usually comes back
        // under the same node, through the udev rule's stable symlink).
        if (Error e = openAndStart(); !e.ok()) return e;
    }
    const int64_t startNs = monotonicNs();
    const int64_t deadline = clock_.monotonicMs() + timeoutMs;
    // Also bounded in real time: a test's manual clock does not move while poll() waits.
    const int64_t realDeadlineNs = startNs + int64_t(timeoutMs) * 1000000;
    Error failure;
    if (Error e = requeueHeld(); !e.ok()) failure = e;
    while (failure.ok()) {
        v4l2_buffer b{};
        b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        b.memory = V4L2_MEMORY_MMAP;
        if (xioctl(fd_.get(), VIDIOC_DQBUF, &b) == 0) {
            const int64_t stampNs = int64_t(b.timestamp.tv_sec) * 1000000000 + int64_t(b.timestamp.tv_usec) * 1000;
            const bool stale = stampNs < startNs; // exposed before the trigger: hand it back
            if (stale || (b.flags & V4L2_BUF_FLAG_ERROR) || int(b.index) >= bufferCount_) {
                if (xioctl(fd_.get(), VIDIOC_QBUF, &b) < 0) failure = Error::make(Errc::Io, sysError("camera: QBUF"));
                continue;
            }
            held_ = int(b.index);
            const size_t used = b.bytesused ? b.bytesused : imageBytes_;
            out->view = {format_, static_cast<const uint8_t *>(buffers_[held_].addr), width_, height_, stride_,
                         used < buffers_[held_].length ? used : buffers_[held_].length};
            out->timestampMs = clock_.monotonicMs() - (monotonicNs() - stampNs) / 1000000;
            out->source = options_.device;
            return {};
        }
        if (errno != EAGAIN) {
            failure = unplugged(errno) ? Error::make(Errc::Closed, sysError("camera " + options_.device + " unplugged"))
                                       : Error::make(Errc::Io, sysError("camera: DQBUF"));
            break;
        }
        int64_t left = deadline - clock_.monotonicMs();
        const int64_t realLeft = (realDeadlineNs - monotonicNs()) / 1000000;
        if (realLeft < left) left = realLeft;
        if (left <= 0) return Error::make(Errc::Timeout, "camera: no frame within " + std::to_string(timeoutMs) + " ms");
        pollfd p{fd_.get(), POLLIN, 0};
        const int pr = ::poll(&p, 1, int(left < 20 ? left : 20)); // short slices: the deadline rules
        if (pr < 0 && errno != EINTR) failure = Error::make(Errc::Io, sysError("camera: poll"));
        else if (pr > 0 && (p.revents & (POLLERR | POLLHUP | POLLNVAL)) && !(p.revents & POLLIN))
            failure = Error::make(Errc::Closed, "camera " + options_.device + " unplugged");
    }
    stop(); // reopened by the next capture()
    return failure;
}

} // namespace icacam::hal
