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

#include <cstdio>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <iterator>
#include <vector>

#include "hal/fresh_frame.h"
#include "hal/v4l2/buffer_stamp.h"
#include "hal/v4l2/mjpeg_luma.h"
#include "hal/v4l2/stream_mode.h"

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

std::string sysError(const std::string &what)
{
    return what + ": " + std::strerror(errno);
}

// An unplugged UVC camera answers ENODEV; the chardev can also report EIO or hang up.
bool unplugged(int err)
{
    return err == ENODEV || err == ENXIO || err == EIO;
}

uint32_t fourcc(PixelFormat f)
{
    switch (f) {
    case PixelFormat::Grey8: return V4L2_PIX_FMT_GREY;
    case PixelFormat::YUYV: return V4L2_PIX_FMT_YUYV;
    case PixelFormat::NV12: return V4L2_PIX_FMT_NV12;
    default: return 0;
    }
}

bool fromFourcc(uint32_t cc, PixelFormat *f)
{
    switch (cc) {
    case V4L2_PIX_FMT_GREY: *f = PixelFormat::Grey8; return true;
    case V4L2_PIX_FMT_YUYV: *f = PixelFormat::YUYV; return true;
    case V4L2_PIX_FMT_NV12: *f = PixelFormat::NV12; return true;
    default: return false;
    }
}

int64_t monotonicNs()
{
    return monotonicNowNs();
}

// Preference among formats of equal size: in place before decoded.
// capture() polls in slices this long, so a buffer waits at most this in the driver's queue.
constexpr int kPollSliceMs = 20;

const uint32_t kFormats[] = {V4L2_PIX_FMT_GREY, V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_MJPEG};

bool known(uint32_t cc)
{
    for (uint32_t k : kFormats)
        if (k == cc) return true;
    return false;
}

// The fastest frame interval the device lists for a format and size (0 / 0: none listed).
void fastestInterval(int fd, uint32_t cc, uint32_t w, uint32_t h, uint32_t *num, uint32_t *den)
{
    *num = *den = 0;
    for (uint32_t i = 0; i < 64; ++i) {
        v4l2_frmivalenum f{};
        f.index = i;
        f.pixel_format = cc;
        f.width = w;
        f.height = h;
        if (xioctl(fd, VIDIOC_ENUM_FRAMEINTERVALS, &f) < 0) return;
        const v4l2_fract t = f.type == V4L2_FRMIVAL_TYPE_DISCRETE ? f.discrete : f.stepwise.min;
        if (t.numerator && t.denominator && (!*den || uint64_t(t.numerator) * *den < uint64_t(*num) * t.denominator))
            *num = t.numerator, *den = t.denominator;
        if (f.type != V4L2_FRMIVAL_TYPE_DISCRETE) return;
    }
}

// Every listed format vision can take, with each listed size (a stepwise or continuous range:
// its largest size within the maximum; none listed: the maximum, for S_FMT to adjust) and
// that size's fastest frame interval. `enumerated`: the device answers ENUM_FMT at all.
void listModes(int fd, int maxW, int maxH, std::vector<V4l2Mode> *out, bool *enumerated)
{
    *enumerated = false;
    for (uint32_t i = 0; i < 64; ++i) {
        v4l2_fmtdesc d{};
        d.index = i;
        d.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (xioctl(fd, VIDIOC_ENUM_FMT, &d) < 0) break;
        *enumerated = true;
        if (!known(d.pixelformat)) continue;
        for (uint32_t k = 0; k < 256; ++k) {
            v4l2_frmsizeenum f{};
            f.index = k;
            f.pixel_format = d.pixelformat;
            if (xioctl(fd, VIDIOC_ENUM_FRAMESIZES, &f) < 0) {
                if (k == 0) out->push_back({d.pixelformat, maxW, maxH, 0, 0});
                break;
            }
            V4l2Mode m;
            m.fourcc = d.pixelformat;
            if (f.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
                m.width = int(f.discrete.width);
                m.height = int(f.discrete.height);
            } else {
                m.width = f.stepwise.max_width < uint32_t(maxW) ? int(f.stepwise.max_width) : maxW;
                m.height = f.stepwise.max_height < uint32_t(maxH) ? int(f.stepwise.max_height) : maxH;
            }
            fastestInterval(fd, m.fourcc, uint32_t(m.width), uint32_t(m.height), &m.intervalNum, &m.intervalDen);
            out->push_back(m);
            if (f.type != V4L2_FRMSIZE_TYPE_DISCRETE) break;
        }
    }
}

bool setControl(int fd, uint32_t id, int32_t value)
{
    v4l2_ext_control c{};
    c.id = id;
    c.value = value;
    v4l2_ext_controls cs{};
    cs.which = V4L2_CTRL_WHICH_CUR_VAL;
    cs.count = 1;
    cs.controls = &c;
    return xioctl(fd, VIDIOC_S_EXT_CTRLS, &cs) == 0;
}

bool getControl(int fd, uint32_t id, int32_t *value)
{
    v4l2_ext_control c{};
    c.id = id;
    v4l2_ext_controls cs{};
    cs.which = V4L2_CTRL_WHICH_CUR_VAL;
    cs.count = 1;
    cs.controls = &c;
    if (xioctl(fd, VIDIOC_G_EXT_CTRLS, &cs) < 0) return false;
    *value = c.value;
    return true;
}

// The driver's range for a control; false when the device has no such control (or it is
// disabled).
bool queryControl(int fd, uint32_t id, v4l2_queryctrl *q)
{
    *q = {};
    q->id = id;
    return xioctl(fd, VIDIOC_QUERYCTRL, q) == 0 && !(q->flags & V4L2_CTRL_FLAG_DISABLED);
}

// v within the driver's range, on its step (uvcvideo clamps the same way; a value read back
// is the one that counts).
int32_t inRange(const v4l2_queryctrl &q, double v)
{
    const double lo = q.minimum, hi = q.maximum, step = q.step > 0 ? q.step : 1;
    const double c = std::min(std::max(v, lo), hi);
    return int32_t(std::min(hi, lo + std::round((c - lo) / step) * step));
}

std::string fourccName(uint32_t cc)
{
    const char n[5] = {char(cc & 0xff), char((cc >> 8) & 0xff), char((cc >> 16) & 0xff), char((cc >> 24) & 0xff), 0};
    return n;
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
{}

V4l2Camera::~V4l2Camera()
{
    stop();
}

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
    if (!fourcc(fmt.format)) return Error::make(Errc::BadFormat, "camera: V4L2 delivers grey8, YUYV or NV12 frames");
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
    if (!fd_.valid()) {
        const Error e = Error::make(errno == ENOENT ? Errc::NotFound : Errc::Io, sysError("camera " + dev));
        description_ = "v4l2 " + e.message;
        return e;
    }

    v4l2_capability cap{};
    if (xioctl(fd_.get(), VIDIOC_QUERYCAP, &cap) < 0) {
        const Error e = Error::make(Errc::Io, sysError("camera " + dev + ": not a V4L2 device"));
        stop();
        return e;
    }
    driver_.assign(reinterpret_cast<const char *>(cap.driver),
                   strnlen(reinterpret_cast<const char *>(cap.driver), sizeof cap.driver));
    const uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || !(caps & V4L2_CAP_STREAMING)) {
        stop();
        return Error::make(Errc::BadFormat, "camera " + dev + ": no streaming video capture");
    }

    if (Error e = negotiate(); !e.ok()) {
        stop();
        return e;
    }
    applyControls();

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
        // vb2 reports the queue's timestamp flags on every buffer, QUERYBUF included.
        if (i == 0) stampModel_ = bufferStampModel(b.flags, driver_);
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
    char mode[256];
    std::snprintf(mode, sizeof mode, "v4l2 %s %s %dx%d %s%s, %.1f fps", dev.c_str(), driver_.c_str(), width_, height_,
                  mjpeg_ ? "MJPEG" : fourccName(fourcc(format_)).c_str(), mjpeg_ ? " (decoded to luma)" : "",
                  1e6 / double(frameIntervalUs_));
    description_ = mode;
    description_ += whiteBalanceReadK_ >= 0 ? ", white balance " + std::to_string(whiteBalanceReadK_) + " K" : "";
    description_ += ", timestamps: " + describeStampModel(stampModel_);
    if (!refused_.empty()) description_ += ", refused: " + refused_;
    return {};
}

Error V4l2Camera::negotiate()
{
    const std::string &dev = options_.device;
    const int fd = fd_.get();
    // The mode from what the device lists (chooseV4l2Mode: 15 fps or more preferred, then
    // the largest area, in-place formats before MJPEG); a configured size the device does
    // not list is asked as it is, in the best format that lists anything up to it. A device
    // that lists nothing is asked with S_FMT in the formats' order, its answer taken as it
    // comes.
    uint32_t order[5];
    size_t n = 0;
    order[n++] = fourcc(wanted_.format);
    for (uint32_t cc : kFormats)
        if (cc != order[0]) order[n++] = cc;
    std::vector<V4l2Mode> modes;
    bool enumerated = false;
    listModes(fd, wanted_.maxWidth, wanted_.maxHeight, &modes, &enumerated);
    const bool sized = options_.width > 0 && options_.height > 0;
    V4l2ModeChoice choice =
        chooseV4l2Mode(modes, wanted_.maxWidth, wanted_.maxHeight, options_.width, options_.height, order[0]);
    if (!choice.found && sized) {
        choice = chooseV4l2Mode(modes, options_.width, options_.height, 0, 0, order[0]);
        choice.mode.width = options_.width;
        choice.mode.height = options_.height;
        choice.mode.intervalNum = choice.mode.intervalDen = 0;
    }
    if (enumerated && !choice.found)
        return Error::make(Errc::BadFormat, "camera " + dev + ": lists none of GREY, NV12, YUYV, MJPEG within " +
                                                std::to_string(wanted_.maxWidth) + "x" +
                                                std::to_string(wanted_.maxHeight));
    mode_ = choice.mode;
    const uint32_t bestCc = choice.mode.fourcc;
    const uint32_t bestW = uint32_t(choice.mode.width), bestH = uint32_t(choice.mode.height);
    v4l2_format f{};
    bool agreed = false;
    for (size_t k = 0; k < n && !agreed; ++k) {
        const uint32_t cc = enumerated ? bestCc : order[k];
        f = {};
        f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        f.fmt.pix.width = enumerated ? bestW : uint32_t(options_.width > 0 ? options_.width : wanted_.maxWidth);
        f.fmt.pix.height = enumerated ? bestH : uint32_t(options_.height > 0 ? options_.height : wanted_.maxHeight);
        f.fmt.pix.pixelformat = cc;
        f.fmt.pix.field = V4L2_FIELD_NONE;
        if (xioctl(fd, VIDIOC_S_FMT, &f) < 0) {
            if (errno == EBUSY || unplugged(errno) || enumerated) break;
            continue;
        }
        // Drivers adjust rather than refuse: any answer vision can view in place, or MJPEG.
        mjpeg_ = f.fmt.pix.pixelformat == V4L2_PIX_FMT_MJPEG;
        agreed = mjpeg_ || fromFourcc(f.fmt.pix.pixelformat, &format_);
        if (enumerated) break;
    }
    if (!agreed) return Error::make(Errc::BadFormat, "camera " + dev + ": none of GREY, NV12, YUYV, MJPEG accepted");
    width_ = int(f.fmt.pix.width);
    height_ = int(f.fmt.pix.height);
    imageBytes_ = f.fmt.pix.sizeimage;
    if (width_ > wanted_.maxWidth || height_ > wanted_.maxHeight)
        return Error::make(Errc::TooLarge, "camera " + dev + ": driver chose " + std::to_string(width_) + "x" +
                                               std::to_string(height_) + ", above the configured maximum");
    if (mjpeg_) {
        format_ = PixelFormat::Grey8;
        stride_ = width_;
        const size_t need = size_t(width_) * size_t(height_);
        if (need > decodedBytes_) {
            decoded_ = std::make_unique<uint8_t[]>(need);
            decodedBytes_ = need;
        }
    } else {
        const int minStride = format_ == PixelFormat::YUYV ? 2 * width_ : width_;
        stride_ = f.fmt.pix.bytesperline ? int(f.fmt.pix.bytesperline) : minStride;
        if (stride_ < minStride)
            return Error::make(Errc::BadStride, "camera " + dev + ": stride " + std::to_string(stride_) + " too short");
    }
    // The chosen mode's fastest interval (a UVC camera otherwise streams at its descriptor's
    // default rate). The interval bounds the exposure and the stamp's delay when nothing
    // better is known: read back what the device took.
    v4l2_streamparm parm{};
    parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (enumerated && choice.mode.intervalNum && choice.mode.intervalDen) {
        parm.parm.capture.timeperframe.numerator = choice.mode.intervalNum;
        parm.parm.capture.timeperframe.denominator = choice.mode.intervalDen;
        (void)xioctl(fd, VIDIOC_S_PARM, &parm); // a device without it keeps its own rate
        parm = {};
        parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    }
    if (xioctl(fd, VIDIOC_G_PARM, &parm) == 0 && parm.parm.capture.timeperframe.denominator > 0 &&
        parm.parm.capture.timeperframe.numerator > 0)
        frameIntervalUs_ =
            int64_t(parm.parm.capture.timeperframe.numerator) * 1000000 / parm.parm.capture.timeperframe.denominator;
    return {};
}

void V4l2Camera::applyControls()
{
    const int fd = fd_.get();
    const CameraControls &c = options_.controls;
    refused_.clear();
    auto set = [&](uint32_t id, double v, const char *name) {
        if (!setControl(fd, id, int32_t(std::lround(v)))) refused_ += std::string(refused_.empty() ? "" : " ") + name;
    };
    // Manual exposure: auto off first (the absolute value is ignored while it is on), and no
    // frame-rate priority, which would let the camera stretch the exposure.
    if (c.exposureUs >= 0) {
        set(V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL, "exposure_auto");
        set(V4L2_CID_EXPOSURE_AUTO_PRIORITY, 0, "exposure_auto_priority");
        set(V4L2_CID_EXPOSURE_ABSOLUTE, c.exposureUs / 100.0, "exposure_absolute");
    }
    if (c.analogueGain >= 0) set(V4L2_CID_GAIN, c.analogueGain, "gain");
    int32_t v = 0;
    if (c.redGain >= 0 && c.blueGain >= 0) {
        set(V4L2_CID_AUTO_WHITE_BALANCE, 0, "white_balance_automatic");
        set(V4L2_CID_RED_BALANCE, c.redGain, "red_balance");
        set(V4L2_CID_BLUE_BALANCE, c.blueGain, "blue_balance");
    } else if (options_.whiteBalanceK >= 0 && getControl(fd, V4L2_CID_WHITE_BALANCE_TEMPERATURE, &v)) {
        // UVC cameras offer a colour temperature, not red/blue gains. Auto off first: the
        // temperature is inactive (not settable) while auto white balance is on.
        set(V4L2_CID_AUTO_WHITE_BALANCE, 0, "white_balance_automatic");
        set(V4L2_CID_WHITE_BALANCE_TEMPERATURE, options_.whiteBalanceK, "white_balance_temperature");
    }
    if (c.lensPosition >= 0) {
        set(V4L2_CID_FOCUS_AUTO, 0, "focus_automatic_continuous");
        set(V4L2_CID_FOCUS_ABSOLUTE, c.lensPosition, "focus_absolute");
    }
    if (c.sharpness >= 0) set(V4L2_CID_SHARPNESS, c.sharpness, "sharpness");
    // What the device reports now: journaled with each frame.
    reported_ = {};
    bool manual = false;
    if (getControl(fd, V4L2_CID_EXPOSURE_AUTO, &v)) manual = v == V4L2_EXPOSURE_MANUAL;
    if (manual && getControl(fd, V4L2_CID_EXPOSURE_ABSOLUTE, &v)) reported_.exposureUs = v * 100;
    if (getControl(fd, V4L2_CID_GAIN, &v)) reported_.analogueGain = v;
    if (getControl(fd, V4L2_CID_RED_BALANCE, &v)) reported_.redGain = v;
    if (getControl(fd, V4L2_CID_BLUE_BALANCE, &v)) reported_.blueGain = v;
    if (getControl(fd, V4L2_CID_FOCUS_ABSOLUTE, &v)) reported_.lensPosition = v;
    if (getControl(fd, V4L2_CID_SHARPNESS, &v)) reported_.sharpness = v;
    whiteBalanceReadK_ = -1;
    const bool autoWhite = getControl(fd, V4L2_CID_AUTO_WHITE_BALANCE, &v) && v != 0;
    if (!autoWhite && getControl(fd, V4L2_CID_WHITE_BALANCE_TEMPERATURE, &v)) whiteBalanceReadK_ = v;
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

Error V4l2Camera::capture(const CaptureRequest &req, CapturedFrame *out)
{
    if (!configured_) return Error::make(Errc::Invalid, "camera: not configured");
    if (!streaming_) {
        // After an unplug: try the device again (the replugged camera usually comes back
        // under the same node, through the udev rule's stable symlink).
        if (Error e = openAndStart(); !e.ok()) return e;
    }
    const int timeoutMs = req.timeoutMs;
    const int64_t startNs = monotonicNs();
    const int64_t notBeforeNs = std::max(notBeforeOnMonotonicNs(clock_, req.notBeforeMs), controlsChangedNs_);
    const int64_t deadline = clock_.monotonicMs() + timeoutMs;
    // Also bounded in real time: a test's manual clock does not move while poll() waits.
    const int64_t realDeadlineNs = startNs + int64_t(timeoutMs) * 1000000;
    // Without a manual exposure read back, the exposure is at most one frame interval.
    BufferTiming timing;
    timing.exposureNs = (reported_.exposureUs > 0 ? int64_t(reported_.exposureUs) : frameIntervalUs_) * 1000;
    timing.frameIntervalNs = frameIntervalUs_ * 1000;
    timing.configuredDelayNs = options_.stampDelayUs >= 0 ? int64_t(options_.stampDelayUs) * 1000 : -1;
    timing.pollSliceNs = int64_t(kPollSliceMs) * 1000000;
    timing.waitingAtCall = true; // until the first poll: buffers filled before this call
    FrameStamp stamp;
    int stale = 0;
    std::string corrupt;
    Error failure;
    if (Error e = requeueHeld(); !e.ok()) failure = e;
    while (failure.ok()) {
        v4l2_buffer b{};
        b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        b.memory = V4L2_MEMORY_MMAP;
        if (xioctl(fd_.get(), VIDIOC_DQBUF, &b) == 0) {
            timing.stampNs = int64_t(b.timestamp.tv_sec) * 1000000000 + int64_t(b.timestamp.tv_usec) * 1000;
            timing.nowNs = monotonicNs();
            const BufferStampModel model = bufferStampModel(b.flags, driver_);
            // Filled before the light settled, in flight across it, or with no believable
            // time at all: hand it back.
            const bool early = !boundExposureStart(model, timing, &stamp) || !exposedAfter(stamp, notBeforeNs);
            bool usable = !early && !(b.flags & V4L2_BUF_FLAG_ERROR) && int(b.index) < bufferCount_;
            stale += early ? 1 : 0;
            const size_t used = b.bytesused ? b.bytesused : imageBytes_;
            const size_t bytes =
                int(b.index) < bufferCount_ && used > buffers_[b.index].length ? buffers_[b.index].length : used;
            if (usable && mjpeg_) {
                const Error d = decodeMjpegLuma(static_cast<const uint8_t *>(buffers_[b.index].addr), bytes,
                                                decoded_.get(), decodedBytes_, width_, height_, stride_);
                if (!d.ok()) {
                    corrupt = d.message; // a torn frame at stream start: the next one will do
                    usable = false;
                }
            }
            if (!usable) {
                if (xioctl(fd_.get(), VIDIOC_QBUF, &b) < 0) failure = Error::make(Errc::Io, sysError("camera: QBUF"));
                continue;
            }
            held_ = int(b.index);
            const uint8_t *pixels = mjpeg_ ? decoded_.get() : static_cast<const uint8_t *>(buffers_[held_].addr);
            out->view = {format_, pixels, width_, height_, stride_, mjpeg_ ? decodedBytes_ : bytes};
            const int64_t exposedNs = exposureStartNs(stamp);
            out->timestampMs = monotonicNsOnClockMs(clock_, exposedNs);
            out->latencyUs = (exposedNs - notBeforeNs) / 1000;
            out->exposureUs = timing.exposureNs / 1000;
            out->sequence = b.sequence;
            out->staleFrames = stale;
            out->stampDelayUs = stamp.stampDelayNs / 1000;
            out->controls = reported_;
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
        if (left <= 0)
            return Error::make(Errc::Timeout, "camera: no frame exposed after the LED settled within " +
                                                  std::to_string(timeoutMs) + " ms (" + std::to_string(stale) +
                                                  " earlier frames refused" + (corrupt.empty() ? "" : "; " + corrupt) +
                                                  ")");
        pollfd p{fd_.get(), POLLIN, 0};
        const int pr =
            ::poll(&p, 1, int(left < kPollSliceMs ? left : kPollSliceMs)); // short slices: the deadline rules
        timing.waitingAtCall = false;
        if (pr < 0 && errno != EINTR)
            failure = Error::make(Errc::Io, sysError("camera: poll"));
        else if (pr > 0 && (p.revents & (POLLERR | POLLHUP | POLLNVAL)) && !(p.revents & POLLIN))
            failure = Error::make(Errc::Closed, "camera " + options_.device + " unplugged");
    }
    stop(); // reopened by the next capture()
    description_ = "v4l2 " + options_.device + ": " + failure.message;
    return failure;
}

Error V4l2Camera::setStampDelayUs(int us)
{
    if (us < 0) return Error::make(Errc::Invalid, "camera: a stamp delay is 0 or more microseconds");
    options_.stampDelayUs = us;
    return {};
}

Result<CameraControls> V4l2Camera::setControls(const CameraControls &asked)
{
    if (!configured_) return Result<CameraControls>::fail(Errc::Invalid, "camera: not configured");
    if (!streaming_)
        if (Error e = openAndStart(); !e.ok()) return {{}, e};
    const int fd = fd_.get();
    // Each control asked, in the device's units (exposure_absolute counts 100 µs steps, UVC
    // 1.5 §4.2.2.1.4), and the automatic one it needs off: all checked against what the
    // driver lists before any is set, so a refusal changes nothing.
    struct Step {
        uint32_t id, autoId;
        int32_t autoManual;
        double value;
        const char *name;
        v4l2_queryctrl range;
    };
    Step steps[6];
    int n = 0;
    std::string missing;
    auto want = [&](bool set, uint32_t id, uint32_t autoId, int32_t autoManual, double value, const char *name) {
        if (!set) return;
        Step &st = steps[n];
        st = {id, autoId, autoManual, value, name, {}};
        if (queryControl(fd, id, &st.range))
            ++n;
        else
            missing += std::string(missing.empty() ? "" : ", ") + name;
    };
    v4l2_queryctrl q{};
    const uint32_t gainId = queryControl(fd, V4L2_CID_GAIN, &q) ? V4L2_CID_GAIN : V4L2_CID_ANALOGUE_GAIN;
    want(asked.exposureUs >= 0, V4L2_CID_EXPOSURE_ABSOLUTE, V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL,
         asked.exposureUs / 100.0, "exposure_absolute");
    want(asked.analogueGain >= 0, gainId, 0, 0, asked.analogueGain, "gain");
    want(asked.redGain >= 0, V4L2_CID_RED_BALANCE, V4L2_CID_AUTO_WHITE_BALANCE, 0, asked.redGain, "red_balance");
    want(asked.blueGain >= 0, V4L2_CID_BLUE_BALANCE, V4L2_CID_AUTO_WHITE_BALANCE, 0, asked.blueGain, "blue_balance");
    want(asked.lensPosition >= 0, V4L2_CID_FOCUS_ABSOLUTE, V4L2_CID_FOCUS_AUTO, 0, asked.lensPosition,
         "focus_absolute");
    want(asked.sharpness >= 0, V4L2_CID_SHARPNESS, 0, 0, asked.sharpness, "sharpness");
    if (asked.noiseReduction >= 0) missing += std::string(missing.empty() ? "" : ", ") + "noise reduction";
    if (!missing.empty())
        return Result<CameraControls>::fail(Errc::Invalid, "camera " + options_.device + " has no " + missing +
                                                               " control (nothing changed)");
    // uvcvideo refuses (EACCES) a value whose automatic control is on: that one goes first.
    // No frame-rate priority either: it would let the camera stretch the exposure.
    for (int i = 0; i < n; ++i) {
        const Step &st = steps[i];
        if (st.autoId) (void)setControl(fd, st.autoId, st.autoManual);
        if (st.id == V4L2_CID_EXPOSURE_ABSOLUTE) (void)setControl(fd, V4L2_CID_EXPOSURE_AUTO_PRIORITY, 0);
        if (!setControl(fd, st.id, inRange(st.range, st.value)))
            return Result<CameraControls>::fail(unplugged(errno) ? Errc::Closed : Errc::Io,
                                                sysError("camera " + options_.device + ": " + st.name));
    }
    mergeControls(&options_.controls, asked); // and after a reconfigure or a replug
    // What the device took: reported with every frame from now on.
    CameraControls took;
    int32_t v = 0;
    if (asked.exposureUs >= 0 && getControl(fd, V4L2_CID_EXPOSURE_ABSOLUTE, &v)) took.exposureUs = v * 100;
    if (asked.analogueGain >= 0 && getControl(fd, gainId, &v)) took.analogueGain = v;
    if (asked.redGain >= 0 && getControl(fd, V4L2_CID_RED_BALANCE, &v)) took.redGain = v;
    if (asked.blueGain >= 0 && getControl(fd, V4L2_CID_BLUE_BALANCE, &v)) took.blueGain = v;
    if (asked.lensPosition >= 0 && getControl(fd, V4L2_CID_FOCUS_ABSOLUTE, &v)) took.lensPosition = v;
    if (asked.sharpness >= 0 && getControl(fd, V4L2_CID_SHARPNESS, &v)) took.sharpness = v;
    mergeControls(&reported_, took);
    // A UVC camera reports nothing per frame: frames exposed before the change, and in the
    // frame interval after it (the camera applies a control at a frame boundary), are old.
    controlsChangedNs_ = monotonicNs() + frameIntervalUs_ * 1000;
    return {took, {}};
}

Result<double> V4l2Camera::focusOnce(int timeoutMs)
{
    if (!configured_) return Result<double>::fail(Errc::Invalid, "camera: not configured");
    if (!streaming_)
        if (Error e = openAndStart(); !e.ok()) return {0, e};
    int32_t v = 0;
    if (!getControl(fd_.get(), V4L2_CID_FOCUS_AUTO, &v) || !getControl(fd_.get(), V4L2_CID_FOCUS_ABSOLUTE, &v))
        return Result<double>::fail(Errc::Invalid, "camera " + options_.device + " has no autofocus");
    if (!setControl(fd_.get(), V4L2_CID_FOCUS_AUTO, 1))
        return Result<double>::fail(Errc::Io, sysError("camera: focus_automatic_continuous"));
    // Settled: the same focus_absolute for kStill frames in a row, after at least one more.
    constexpr int kStill = 5;
    const int64_t deadline = clock_.monotonicMs() + timeoutMs;
    int32_t last = -1;
    int still = 0, frames = 0;
    while (clock_.monotonicMs() < deadline) {
        CapturedFrame frame;
        if (Error e = capture(CaptureRequest{CaptureRequest::kAtCall, timeoutMs}, &frame); !e.ok()) return {0, e};
        if (!getControl(fd_.get(), V4L2_CID_FOCUS_ABSOLUTE, &v)) break; // inactive while auto: no reading
        still = v == last ? still + 1 : 0;
        last = v;
        if (++frames > kStill && still >= kStill) {
            CameraControls hold;
            hold.lensPosition = v;
            if (const auto r = setControls(hold); !r.ok()) return {0, r.error};
            return {double(v), {}};
        }
    }
    CameraControls before;
    before.lensPosition = options_.controls.lensPosition;
    if (before.lensPosition >= 0)
        (void)setControls(before);
    else
        (void)setControl(fd_.get(), V4L2_CID_FOCUS_AUTO, 0);
    return Result<double>::fail(Errc::Timeout, "camera " + options_.device + ": focus did not settle within " +
                                                   std::to_string(timeoutMs) + " ms");
}

} // namespace icacam::hal
