// The V4L2 camera against a mocked /dev/video0 (umockdev): the backend's real ioctl sequence
// (QUERYCAP, S_FMT, REQBUFS, QUERYBUF, QBUF, STREAMON, DQBUF, STREAMOFF) is answered here the
// way a UVC driver would; the buffer memory comes from the test through the mapper seam,
// since umockdev does not wrap mmap (PLATFORM.md). Exits 77 without the preload library.
//
// Frames are "exposed" with the timestamps uvcvideo gives them (the first USB packet: after
// the exposure), so the tests can hold stale ones, ones in flight when the LED settled and
// fresh ones in the driver's queue, in the order the driver delivers them.
#include <gtest/gtest.h>

#include <jpeglib.h>

#include <linux/videodev2.h>
#include <time.h>
#include <umockdev.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "firmware/device.h"
#include "firmware/font5x7.h"
#include "friction/paper_model.h"
#include "hal/file/clocks.h"
#include "hal/file/folder_storage.h"
#include "hal/v4l2/v4l2_camera.h"
#include "tests/hal/c920_modes.h"
#include "tests/support/recording_serial.h"
#include "tests/support/umockdev_mock.h"

namespace {

using namespace icacam;

constexpr uint32_t kOffsetStep = 1u << 24; // buffer i's mmap offset

int64_t nowNs()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// The driver's side: formats it accepts, its buffers and their state, frames "exposed".
struct FakeVideo {
    std::mutex m;
    std::vector<uint32_t> formats{V4L2_PIX_FMT_YUYV}; // what S_FMT accepts (first = default)
    uint32_t width = 64, height = 48;
    std::vector<std::vector<uint8_t>> memory;
    std::vector<bool> queued;
    struct Frame {
        int64_t ns;
        uint8_t fill;
        int bottomFill = -1; // >= 0: the bottom half's rows (a frame the light reached in part)
    };
    std::deque<Frame> exposures; // frames the sensor will deliver, into the next queued buffer
    std::vector<uint8_t> jpeg;   // MJPEG: every frame's bytes
    bool streaming = false, unplugged = false;
    // What a UVC camera lists: formats with their discrete sizes (empty: ENUM_FMT unsupported).
    std::vector<std::pair<uint32_t, std::vector<std::pair<uint32_t, uint32_t>>>> listed;
    std::map<uint32_t, int32_t> controls; // supported controls and their values
    // QUERYCTRL's minimum, maximum and step per control (absent: 0 … 1 000 000 in steps of 1).
    std::map<uint32_t, std::tuple<int32_t, int32_t, int32_t>> ranges;
    uint32_t intervalNum = 0, intervalDen = 0; // G_PARM (0: unsupported); S_PARM sets it
    // ENUM_FRAMEINTERVALS: frame rates (frames per second, discrete) per format and size.
    std::map<std::tuple<uint32_t, uint32_t, uint32_t>, std::vector<uint32_t>> rates;
    bool sParmSeen = false;
    // What a buffer's flags say about its timestamp. uvcvideo's queue: MONOTONIC | SOE,
    // set once in uvc_queue_init (drivers/media/usb/uvc/uvc_queue.c).
    uint32_t stampFlags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_TSTAMP_SRC_SOE;
    const char *driver = "uvcvideo";
    uint32_t sequence = 0;
    uint32_t pixfmt = 0;
    std::vector<unsigned long> seen; // request codes, in order
};

gboolean onIoctl(UMockdevIoctlBase *, UMockdevIoctlClient *client, gpointer user)
{
    auto *v = static_cast<FakeVideo *>(user);
    std::lock_guard<std::mutex> lock(v->m);
    const unsigned long req = umockdev_ioctl_client_get_request(client);
    v->seen.push_back(req);
    auto done = [&](int err) {
        umockdev_ioctl_client_complete(client, err ? -1 : 0, err);
        return TRUE;
    };
    if (v->unplugged) return done(ENODEV);
    switch (req) {
    case VIDIOC_ENUM_FMT: {
        auto *d = test::ioctlArg<v4l2_fmtdesc>(client);
        if (!d) return done(EFAULT);
        if (v->listed.empty()) return done(ENOTTY);
        if (d->index >= v->listed.size()) return done(EINVAL);
        d->pixelformat = v->listed[d->index].first;
        return done(0);
    }
    case VIDIOC_ENUM_FRAMESIZES: {
        auto *f = test::ioctlArg<v4l2_frmsizeenum>(client);
        if (!f) return done(EFAULT);
        for (const auto &l : v->listed)
            if (l.first == f->pixel_format && f->index < l.second.size()) {
                f->type = V4L2_FRMSIZE_TYPE_DISCRETE;
                f->discrete.width = l.second[f->index].first;
                f->discrete.height = l.second[f->index].second;
                return done(0);
            }
        return done(EINVAL);
    }
    case VIDIOC_ENUM_FRAMEINTERVALS: {
        auto *f = test::ioctlArg<v4l2_frmivalenum>(client);
        if (!f) return done(EFAULT);
        const auto it = v->rates.find({f->pixel_format, f->width, f->height});
        if (it == v->rates.end() || f->index >= it->second.size()) return done(EINVAL);
        f->type = V4L2_FRMIVAL_TYPE_DISCRETE;
        f->discrete.numerator = 1;
        f->discrete.denominator = it->second[f->index];
        return done(0);
    }
    case VIDIOC_G_PARM: {
        auto *p = test::ioctlArg<v4l2_streamparm>(client);
        if (!p) return done(EFAULT);
        if (!v->intervalDen) return done(ENOTTY);
        p->parm.capture.timeperframe.numerator = v->intervalNum;
        p->parm.capture.timeperframe.denominator = v->intervalDen;
        return done(0);
    }
    case VIDIOC_S_PARM: {
        auto *p = test::ioctlArg<v4l2_streamparm>(client);
        if (!p) return done(EFAULT);
        if (v->rates.empty()) return done(ENOTTY);
        v->sParmSeen = true;
        v->intervalNum = p->parm.capture.timeperframe.numerator;
        v->intervalDen = p->parm.capture.timeperframe.denominator;
        return done(0);
    }
    case VIDIOC_S_EXT_CTRLS:
    case VIDIOC_G_EXT_CTRLS: {
        // The control array is a pointer inside the argument: resolved from the struct.
        UMockdevIoctlData *arg = umockdev_ioctl_client_get_arg(client);
        UMockdevIoctlData *sd = arg ? umockdev_ioctl_data_resolve(arg, 0, sizeof(v4l2_ext_controls), nullptr) : nullptr;
        if (!sd) return done(EFAULT);
        auto *cs = reinterpret_cast<v4l2_ext_controls *>(sd->data);
        if (cs->count != 1) return done(EINVAL);
        UMockdevIoctlData *cd =
            umockdev_ioctl_data_resolve(sd, offsetof(v4l2_ext_controls, controls), sizeof(v4l2_ext_control), nullptr);
        if (!cd) return done(EFAULT);
        auto *c = reinterpret_cast<v4l2_ext_control *>(cd->data);
        auto it = v->controls.find(c->id);
        if (it == v->controls.end()) return done(EINVAL);
        if (req == VIDIOC_S_EXT_CTRLS)
            it->second = c->value;
        else
            c->value = it->second;
        return done(0);
    }
    case VIDIOC_QUERYCTRL: {
        auto *q = test::ioctlArg<v4l2_queryctrl>(client);
        if (!q) return done(EFAULT);
        if (!v->controls.count(q->id)) return done(EINVAL);
        const auto r = v->ranges.count(q->id) ? v->ranges[q->id] : std::make_tuple(0, 1000000, 1);
        q->type = V4L2_CTRL_TYPE_INTEGER;
        q->minimum = std::get<0>(r);
        q->maximum = std::get<1>(r);
        q->step = std::get<2>(r);
        q->flags = 0;
        return done(0);
    }
    case VIDIOC_QUERYCAP: {
        auto *c = test::ioctlArg<v4l2_capability>(client);
        if (!c) return done(EFAULT);
        *c = {};
        std::snprintf(reinterpret_cast<char *>(c->driver), sizeof c->driver, "%s", v->driver);
        c->capabilities = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING | V4L2_CAP_DEVICE_CAPS;
        c->device_caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
        return done(0);
    }
    case VIDIOC_S_FMT: {
        auto *f = test::ioctlArg<v4l2_format>(client);
        if (!f || f->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return done(EINVAL);
        bool ok = false;
        for (uint32_t cc : v->formats) ok = ok || cc == f->fmt.pix.pixelformat;
        if (!ok) f->fmt.pix.pixelformat = v->formats.front(); // drivers adjust, not refuse
        v->pixfmt = f->fmt.pix.pixelformat;
        f->fmt.pix.width = std::min(f->fmt.pix.width, v->width);
        f->fmt.pix.height = std::min(f->fmt.pix.height, v->height);
        const uint32_t bpp = v->pixfmt == V4L2_PIX_FMT_YUYV ? 2 : 1;
        f->fmt.pix.bytesperline = f->fmt.pix.width * bpp;
        f->fmt.pix.sizeimage =
            f->fmt.pix.bytesperline * f->fmt.pix.height * (v->pixfmt == V4L2_PIX_FMT_NV12 ? 3 : 2) / 2;
        if (v->pixfmt != V4L2_PIX_FMT_NV12) f->fmt.pix.sizeimage = f->fmt.pix.bytesperline * f->fmt.pix.height;
        return done(0);
    }
    case VIDIOC_REQBUFS: {
        auto *r = test::ioctlArg<v4l2_requestbuffers>(client);
        if (!r || r->memory != V4L2_MEMORY_MMAP) return done(EINVAL);
        if (v->streaming) return done(EBUSY);
        v->memory.assign(r->count, std::vector<uint8_t>(size_t(v->width) * v->height * 2));
        v->queued.assign(r->count, false);
        return done(0);
    }
    case VIDIOC_QUERYBUF:
    case VIDIOC_QBUF: {
        auto *b = test::ioctlArg<v4l2_buffer>(client);
        if (!b || b->index >= v->memory.size()) return done(EINVAL);
        if (req == VIDIOC_QUERYBUF) {
            b->length = uint32_t(v->memory[b->index].size());
            b->m.offset = b->index * kOffsetStep;
            b->flags = v->stampFlags;
        } else {
            if (v->queued[b->index]) return done(EINVAL);
            v->queued[b->index] = true;
        }
        return done(0);
    }
    case VIDIOC_STREAMON: v->streaming = true; return done(0);
    case VIDIOC_STREAMOFF:
        v->streaming = false;
        v->queued.assign(v->queued.size(), false);
        return done(0);
    case VIDIOC_DQBUF: {
        auto *b = test::ioctlArg<v4l2_buffer>(client);
        if (!b) return done(EFAULT);
        if (!v->streaming) return done(EINVAL);
        size_t i = 0;
        while (i < v->queued.size() && !v->queued[i]) ++i;
        if (v->exposures.empty() || i == v->queued.size()) return done(EAGAIN);
        const FakeVideo::Frame fr = v->exposures.front();
        v->exposures.pop_front();
        v->queued[i] = false;
        b->index = uint32_t(i);
        if (v->pixfmt == V4L2_PIX_FMT_MJPEG) {
            std::copy(v->jpeg.begin(), v->jpeg.end(), v->memory[i].begin());
            b->bytesused = uint32_t(v->jpeg.size());
        } else {
            std::fill(v->memory[i].begin(), v->memory[i].end(), fr.fill);
            if (fr.bottomFill >= 0)
                std::fill(v->memory[i].begin() + ptrdiff_t(v->width * 2 * (v->height / 2)),
                          v->memory[i].begin() + ptrdiff_t(v->width * 2 * v->height), uint8_t(fr.bottomFill));
            b->bytesused = v->width * v->height * 2;
        }
        b->sequence = v->sequence++;
        b->flags = v->stampFlags;
        b->timestamp.tv_sec = fr.ns / 1000000000;
        b->timestamp.tv_usec = (fr.ns % 1000000000) / 1000;
        return done(0);
    }
    default: return done(ENOTTY);
    }
}

// The test's side of mmap: buffer i's memory for offset i × kOffsetStep.
struct TestMapper final : hal::V4l2BufferMapper {
    FakeVideo *video = nullptr;
    int mapped = 0;
    void *map(int, size_t length, uint32_t offset) override
    {
        std::lock_guard<std::mutex> lock(video->m);
        const size_t i = offset / kOffsetStep;
        if (i >= video->memory.size() || length > video->memory[i].size()) return nullptr;
        ++mapped;
        return video->memory[i].data();
    }
    void unmap(void *, size_t) override { --mapped; }
};

hal::V4l2Options opts(const char *device, int buffers)
{
    hal::V4l2Options o;
    o.device = device;
    o.bufferCount = buffers;
    return o;
}

// A grey gradient as one baseline JPEG, as a UVC camera sends it.
std::vector<uint8_t> encodeJpeg(int w, int h)
{
    std::vector<uint8_t> grey(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) grey[size_t(y) * size_t(w) + size_t(x)] = uint8_t((x + y) / 5 % 256);
    jpeg_compress_struct c;
    jpeg_error_mgr err;
    c.err = jpeg_std_error(&err);
    jpeg_create_compress(&c);
    unsigned char *mem = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&c, &mem, &size);
    c.image_width = JDIMENSION(w);
    c.image_height = JDIMENSION(h);
    c.input_components = 3;
    c.in_color_space = JCS_RGB;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, 95, TRUE);
    jpeg_start_compress(&c, TRUE);
    std::vector<uint8_t> row(size_t(w) * 3);
    while (c.next_scanline < c.image_height) {
        for (int x = 0; x < w; ++x)
            row[size_t(x) * 3] = row[size_t(x) * 3 + 1] = row[size_t(x) * 3 + 2] =
                grey[size_t(c.next_scanline) * size_t(w) + size_t(x)];
        JSAMPROW r = row.data();
        jpeg_write_scanlines(&c, &r, 1);
    }
    jpeg_finish_compress(&c);
    std::vector<uint8_t> out(mem, mem + size);
    jpeg_destroy_compress(&c);
    free(mem);
    return out;
}

class V4l2Mock : public ::testing::Test {
protected:
    void SetUp() override
    {
        bed_ = umockdev_testbed_new();
        GError *err = nullptr;
        const char *dev = "P: /devices/pci0000:00/usb1/1-1/1-1:1.0/video4linux/video0\n"
                          "N: video0\n"
                          "E: SUBSYSTEM=video4linux\n"
                          "E: DEVNAME=/dev/video0\n"
                          "A: dev=81:0\\n\n"
                          "A: name=Mock UVC Camera\n";
        ASSERT_TRUE(umockdev_testbed_add_from_string(bed_, dev, &err)) << (err ? err->message : "");
        handler_ = umockdev_ioctl_base_new();
        g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(onIoctl), &video_);
        ASSERT_TRUE(umockdev_testbed_attach_ioctl(bed_, "/dev/video0", handler_, &err)) << (err ? err->message : "");
        mapper_.video = &video_;
    }
    void TearDown() override
    {
        if (handler_) g_object_unref(handler_);
        if (bed_) g_object_unref(bed_);
    }
    void expose(int64_t ns, uint8_t fill)
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.exposures.push_back({ns, fill});
    }

    UMockdevTestbed *bed_ = nullptr;
    UMockdevIoctlBase *handler_ = nullptr;
    FakeVideo video_;
    TestMapper mapper_;
    hal::SystemClock clock_;
};

TEST_F(V4l2Mock, NegotiatesAFormatTheDriverHasAndStreams)
{
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 3), &mapper_);
    hal::Error e = cam.configure({hal::PixelFormat::Grey8, 640, 480});
    ASSERT_TRUE(e.ok()) << e.message;
    // GREY asked for, the driver only has YUYV: taken, luma viewed with a pixel step of 2.
    EXPECT_EQ(cam.format(), hal::PixelFormat::YUYV);
    EXPECT_EQ(cam.width(), 64);
    EXPECT_EQ(cam.stride(), 128);
    EXPECT_EQ(mapper_.mapped, 3);
    {
        std::lock_guard<std::mutex> lock(video_.m);
        EXPECT_TRUE(video_.streaming);
        // The streaming sequence (the enumeration and control queries between are optional).
        std::vector<unsigned long> seen;
        for (unsigned long r : video_.seen)
            if (r != VIDIOC_ENUM_FMT && r != VIDIOC_G_PARM && r != VIDIOC_S_EXT_CTRLS && r != VIDIOC_G_EXT_CTRLS &&
                r != VIDIOC_ENUM_FRAMESIZES && r != VIDIOC_ENUM_FRAMEINTERVALS && r != VIDIOC_S_PARM)
                seen.push_back(r);
        const std::vector<unsigned long> start{VIDIOC_QUERYCAP, VIDIOC_S_FMT,    VIDIOC_REQBUFS, VIDIOC_QUERYBUF,
                                               VIDIOC_QBUF,     VIDIOC_QUERYBUF, VIDIOC_QBUF,    VIDIOC_QUERYBUF,
                                               VIDIOC_QBUF,     VIDIOC_STREAMON};
        EXPECT_EQ(seen, start);
    }
}

TEST_F(V4l2Mock, MjpegOnlyCameraIsDecodedToLumaAtTheLargestListedSizeThatFits)
{
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.formats = {V4L2_PIX_FMT_MJPEG};
        video_.width = 1280;
        video_.height = 720;
        // Uncompressed only at a small size, MJPEG up to 720p: MJPEG 640x480 is the largest
        // within an 800x600 maximum.
        video_.listed = {{V4L2_PIX_FMT_YUYV, {{320, 240}}},
                         {V4L2_PIX_FMT_MJPEG, {{320, 240}, {640, 480}, {1280, 720}}}};
        video_.jpeg = encodeJpeg(640, 480);
    }
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    hal::Error e = cam.configure({hal::PixelFormat::Grey8, 800, 600});
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_TRUE(cam.mjpeg());
    EXPECT_EQ(cam.width(), 640);
    EXPECT_EQ(cam.height(), 480);
    EXPECT_EQ(cam.format(), hal::PixelFormat::Grey8);
    expose(nowNs() + 1000000000, 0);
    hal::CapturedFrame frame;
    e = cam.capture(500, &frame);
    ASSERT_TRUE(e.ok()) << e.message;
    ASSERT_EQ(frame.view.width, 640);
    // The decoded luma is the gradient that was encoded (JPEG's error is a few levels).
    int worst = 0;
    for (int y = 0; y < 480; y += 37)
        for (int x = 0; x < 640; x += 41)
            worst = std::max(worst, std::abs(int(frame.view.data[size_t(y) * 640 + size_t(x)]) - (x + y) / 5 % 256));
    EXPECT_LE(worst, 6);
}

TEST_F(V4l2Mock, CorruptMjpegFrameIsSkippedNotMeasured)
{
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.formats = {V4L2_PIX_FMT_MJPEG};
        video_.listed = {{V4L2_PIX_FMT_MJPEG, {{64, 48}}}};
        video_.jpeg = encodeJpeg(64, 48);
        video_.jpeg.resize(video_.jpeg.size() / 3); // torn in transfer
    }
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::Grey8, 640, 480}).ok());
    expose(nowNs() + 1000000000, 0);
    hal::CapturedFrame frame;
    const hal::Error e = cam.capture(150, &frame);
    EXPECT_EQ(e.code, hal::Errc::Timeout) << e.message;
    EXPECT_NE(e.message.find("MJPEG"), std::string::npos) << e.message;
}

TEST_F(V4l2Mock, ImagingControlsAreSetAndReadBack)
{
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.controls = {{V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_APERTURE_PRIORITY},
                           {V4L2_CID_EXPOSURE_AUTO_PRIORITY, 1},
                           {V4L2_CID_EXPOSURE_ABSOLUTE, 156},
                           {V4L2_CID_GAIN, 0},
                           {V4L2_CID_AUTO_WHITE_BALANCE, 1},
                           {V4L2_CID_FOCUS_AUTO, 1},
                           {V4L2_CID_FOCUS_ABSOLUTE, 0}};
    }
    hal::V4l2Options o = opts("/dev/video0", 2);
    o.controls.exposureUs = 8000;
    o.controls.analogueGain = 12;
    o.controls.redGain = 1.5; // this camera has no red/blue balance: refused, not fatal
    o.controls.blueGain = 1.5;
    o.controls.lensPosition = 250;
    hal::V4l2Camera cam(clock_, o, &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    {
        std::lock_guard<std::mutex> lock(video_.m);
        EXPECT_EQ(video_.controls[V4L2_CID_EXPOSURE_AUTO], V4L2_EXPOSURE_MANUAL);
        EXPECT_EQ(video_.controls[V4L2_CID_EXPOSURE_AUTO_PRIORITY], 0);
        EXPECT_EQ(video_.controls[V4L2_CID_EXPOSURE_ABSOLUTE], 80); // 100 us steps
        EXPECT_EQ(video_.controls[V4L2_CID_AUTO_WHITE_BALANCE], 0);
        EXPECT_EQ(video_.controls[V4L2_CID_FOCUS_AUTO], 0);
        EXPECT_EQ(video_.controls[V4L2_CID_FOCUS_ABSOLUTE], 250);
        video_.controls[V4L2_CID_GAIN] = 11; // the camera rounds: what it reports is journaled
    }
    EXPECT_NE(cam.describe().find("red_balance"), std::string::npos) << cam.describe();
    hal::CapturedFrame frame;
    expose(nowNs() + 1000000000, 5);
    ASSERT_TRUE(cam.capture(500, &frame).ok());
    EXPECT_EQ(frame.controls.exposureUs, 8000);
    EXPECT_EQ(frame.controls.lensPosition, 250);
    EXPECT_EQ(frame.controls.analogueGain, 12); // read back right after setting
    EXPECT_LT(frame.controls.redGain, 0);       // not reported
}

TEST_F(V4l2Mock, ControlsChangeOnTheStreamingCameraWithinTheDriversRanges)
{
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.controls = {{V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_APERTURE_PRIORITY},
                           {V4L2_CID_EXPOSURE_AUTO_PRIORITY, 1},
                           {V4L2_CID_EXPOSURE_ABSOLUTE, 156},
                           {V4L2_CID_GAIN, 0},
                           {V4L2_CID_FOCUS_AUTO, 1},
                           {V4L2_CID_FOCUS_ABSOLUTE, 0}};
        // A C920's ranges (uvcvideo from the camera's GET_MIN / GET_MAX / GET_RES).
        video_.ranges = {{V4L2_CID_EXPOSURE_ABSOLUTE, {3, 2047, 1}},
                         {V4L2_CID_GAIN, {0, 255, 1}},
                         {V4L2_CID_FOCUS_ABSOLUTE, {0, 250, 5}}};
    }
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    size_t before = 0;
    {
        std::lock_guard<std::mutex> lock(video_.m);
        before = video_.seen.size();
    }
    hal::CameraControls asked;
    asked.exposureUs = 12000;
    asked.analogueGain = 300; // above the range: the driver's maximum
    asked.lensPosition = 123; // between steps of 5: the nearest
    const hal::Result<hal::CameraControls> took = cam.setControls(asked);
    ASSERT_TRUE(took.ok()) << took.error.message;
    EXPECT_EQ(took.value.exposureUs, 12000);
    EXPECT_EQ(took.value.analogueGain, 255);
    EXPECT_EQ(took.value.lensPosition, 125);
    {
        std::lock_guard<std::mutex> lock(video_.m);
        EXPECT_EQ(video_.controls[V4L2_CID_EXPOSURE_AUTO], V4L2_EXPOSURE_MANUAL); // auto off first
        EXPECT_EQ(video_.controls[V4L2_CID_EXPOSURE_AUTO_PRIORITY], 0);
        EXPECT_EQ(video_.controls[V4L2_CID_EXPOSURE_ABSOLUTE], 120); // 100 µs steps
        EXPECT_EQ(video_.controls[V4L2_CID_GAIN], 255);
        EXPECT_EQ(video_.controls[V4L2_CID_FOCUS_AUTO], 0);
        EXPECT_EQ(video_.controls[V4L2_CID_FOCUS_ABSOLUTE], 125);
        // On the running stream: no stream off, no buffers freed or asked again.
        for (size_t i = before; i < video_.seen.size(); ++i) {
            EXPECT_NE(video_.seen[i], VIDIOC_STREAMOFF);
            EXPECT_NE(video_.seen[i], VIDIOC_REQBUFS);
            EXPECT_NE(video_.seen[i], VIDIOC_S_FMT);
        }
        EXPECT_TRUE(video_.streaming);
    }
    // A frame exposed before the change is the old exposure: not handed out, even to a capture
    // that would take any frame (its LED settled long ago); the one after is, reporting what
    // the device took.
    const int64_t now = nowNs();
    expose(now - 5000000, 1);
    expose(now + 1000000000, 2);
    hal::CapturedFrame frame;
    ASSERT_TRUE(cam.capture(hal::CaptureRequest{0, 1500}, &frame).ok());
    EXPECT_EQ(frame.view.data[0], 2);
    EXPECT_GE(frame.staleFrames, 1);
    EXPECT_EQ(frame.controls.exposureUs, 12000);
    EXPECT_EQ(frame.controls.analogueGain, 255);
    EXPECT_EQ(frame.controls.lensPosition, 125);
}

TEST_F(V4l2Mock, AControlTheCameraLacksChangesNothing)
{
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.controls = {{V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_APERTURE_PRIORITY},
                           {V4L2_CID_EXPOSURE_ABSOLUTE, 156}};
    }
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    hal::CameraControls asked;
    asked.exposureUs = 20000;
    asked.lensPosition = 100; // a fixed-focus webcam
    const hal::Result<hal::CameraControls> took = cam.setControls(asked);
    EXPECT_EQ(took.error.code, hal::Errc::Invalid);
    EXPECT_NE(took.error.message.find("focus_absolute"), std::string::npos) << took.error.message;
    std::lock_guard<std::mutex> lock(video_.m);
    EXPECT_EQ(video_.controls[V4L2_CID_EXPOSURE_ABSOLUTE], 156);
    EXPECT_EQ(video_.controls[V4L2_CID_EXPOSURE_AUTO], V4L2_EXPOSURE_APERTURE_PRIORITY);
}

TEST_F(V4l2Mock, SkipsFramesExposedBeforeTheTriggerAndRecyclesBuffers)
{
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    const int64_t t = nowNs();
    expose(t - 50000000, 11);   // stale: exposed 50 ms before capture() was called
    expose(t + 1000000000, 22); // after the trigger
    hal::CapturedFrame frame;
    hal::Error e = cam.capture(500, &frame);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(frame.view.format, hal::PixelFormat::YUYV);
    ASSERT_NE(frame.view.data, nullptr);
    EXPECT_EQ(frame.view.data[0], 22);
    EXPECT_EQ(frame.view.stride, 128);
    // Ten more frames with two buffers: only works if every buffer goes back to the driver.
    for (int i = 0; i < 10; ++i) {
        expose(nowNs() + 1000000000, uint8_t(100 + i));
        ASSERT_TRUE(cam.capture(500, &frame).ok()) << i;
        EXPECT_EQ(frame.view.data[0], 100 + i);
    }
}

// The LED settles at L; uvcvideo's queue holds a frame exposed long before, then the frame
// whose exposure began 3 ms before L (in flight: stamped after L), then one begun 3 ms after.
// Only the last is measured, with its latency and the count of refused ones.
TEST_F(V4l2Mock, OnlyAFrameExposedAfterTheLedSettledIsHandedOut)
{
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.controls = {{V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL}, {V4L2_CID_EXPOSURE_ABSOLUTE, 100}};
        video_.intervalNum = 1;
        video_.intervalDen = 30;
    }
    hal::V4l2Options o = opts("/dev/video0", 4);
    o.controls.exposureUs = 10000;
    o.stampDelayUs = 2000; // this camera's first packet: within 2 ms of the exposure's end
    hal::V4l2Camera cam(clock_, o, &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    EXPECT_EQ(cam.frameIntervalUs(), 33333);
    const int64_t settleInMs = 40;
    const int64_t litMs = clock_.monotonicMs() + settleInMs;
    const int64_t L = nowNs() + settleInMs * 1000000; // the same instant on the kernel's clock (±1 ms)
    const int64_t exposure = 10000000, delay = 2000000;
    expose(L - 60000000, 1);                   // stale: filled before the LED came on
    expose(L - 3000000 + exposure + delay, 2); // in flight: began 3 ms before L
    expose(L + 3000000 + exposure + delay, 3); // fresh: began 3 ms after L
    expose(L + 3000000 + exposure + delay + 33333333, 4);
    hal::CapturedFrame frame;
    const hal::Error e = cam.capture({litMs, 500}, &frame);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(frame.view.data[0], 3);
    EXPECT_EQ(frame.staleFrames, 2);
    EXPECT_EQ(frame.sequence, 2u);
    EXPECT_NEAR(double(frame.latencyUs), 3000, 1500);
    EXPECT_EQ(frame.exposureUs, 10000);
    EXPECT_EQ(frame.controls.exposureUs, 10000);
}

// A C920-class webcam (tests/hal/c920_modes.h): the largest area is YUYV 2304x1536 at 2 fps,
// which keeps the LED on for half a second a press. The choice is MJPEG 1920x1080 at 30 fps,
// and the interval is asked for (S_PARM), not left at the camera's default.
TEST_F(V4l2Mock, AWebcamStreamsItsLargestModeThatKeepsFifteenFramesASecond)
{
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.formats = {V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_MJPEG};
        video_.width = 2304;
        video_.height = 1536;
        video_.listed.clear();
        for (uint32_t cc : {V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_MJPEG}) {
            std::vector<std::pair<uint32_t, uint32_t>> sizes;
            for (const hal::V4l2Mode &m : test::c920Modes())
                if (m.fourcc == cc) {
                    sizes.emplace_back(uint32_t(m.width), uint32_t(m.height));
                    video_.rates[{cc, uint32_t(m.width), uint32_t(m.height)}] = {m.intervalDen, m.intervalDen / 2};
                }
            video_.listed.emplace_back(cc, sizes);
        }
        video_.intervalNum = 1; // the camera's default: its slowest
        video_.intervalDen = 2;
    }
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    const hal::Error e = cam.configure({hal::PixelFormat::Grey8, 4096, 3072});
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_TRUE(cam.mjpeg());
    EXPECT_EQ(cam.width(), 1920);
    EXPECT_EQ(cam.height(), 1080);
    EXPECT_EQ(cam.frameIntervalUs(), 33333);
    EXPECT_NE(cam.describe().find("30.0 fps"), std::string::npos) << cam.describe();
    std::lock_guard<std::mutex> lock(video_.m);
    EXPECT_TRUE(video_.sParmSeen);
    EXPECT_EQ(video_.pixfmt, uint32_t(V4L2_PIX_FMT_MJPEG));
}

TEST_F(V4l2Mock, WhiteBalanceIsFixedAtAColourTemperature)
{
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.controls = {{V4L2_CID_AUTO_WHITE_BALANCE, 1}, {V4L2_CID_WHITE_BALANCE_TEMPERATURE, 4000}};
    }
    hal::V4l2Options o = opts("/dev/video0", 2);
    o.whiteBalanceK = 5200;
    hal::V4l2Camera cam(clock_, o, &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    EXPECT_EQ(cam.whiteBalanceK(), 5200);
    EXPECT_NE(cam.describe().find("white balance 5200 K"), std::string::npos) << cam.describe();
    std::lock_guard<std::mutex> lock(video_.m);
    EXPECT_EQ(video_.controls[V4L2_CID_AUTO_WHITE_BALANCE], 0);
    EXPECT_EQ(video_.controls[V4L2_CID_WHITE_BALANCE_TEMPERATURE], 5200);
}

// Timestamps that cannot be believed: a buffer that was already waiting when capture() was
// called is refused, whatever its stamp says; one that arrives while it polls is bounded
// by its dequeue time.
TEST_F(V4l2Mock, ABufferWithoutAClockThatWasWaitingIsRefused)
{
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.stampFlags = V4L2_BUF_FLAG_TIMESTAMP_COPY;
        video_.driver = "vivid";
    }
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    EXPECT_NE(cam.describe().find("dequeue time"), std::string::npos) << cam.describe();
    expose(nowNs() + 1000000000, 11); // looks fresh, was waiting before the call
    std::thread later([this] {
        ::usleep(200000);
        expose(0, 22);
    });
    hal::CapturedFrame frame;
    const hal::Error e = cam.capture(1500, &frame);
    later.join();
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(frame.view.data[0], 22);
    EXPECT_EQ(frame.staleFrames, 1);
    EXPECT_GE(frame.latencyUs, 0);
}

// uvcvideo's `clock=realtime` module parameter: wall-clock stamps under the MONOTONIC flag.
// Taken for monotonic, a frame exposed before the call would look decades fresh.
TEST_F(V4l2Mock, WallClockStampsFromUvcvideoAreNotTakenForMonotonicOnes)
{
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    timespec wall{};
    clock_gettime(CLOCK_REALTIME, &wall);
    const int64_t wallNs = int64_t(wall.tv_sec) * 1000000000 + wall.tv_nsec;
    expose(wallNs - 50000000, 11); // exposed 50 ms before the call
    std::thread later([this, wallNs] {
        ::usleep(200000);
        expose(wallNs + 200000000, 22);
    });
    hal::CapturedFrame frame;
    const hal::Error e = cam.capture(1500, &frame);
    later.join();
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(frame.view.data[0], 22);
    EXPECT_EQ(frame.staleFrames, 1);
}

// A driver that stamps at the end of the frame: the first row's exposure ended up to a whole
// readout (one interval) earlier, whatever stamp delay is configured for first packets.
TEST_F(V4l2Mock, AnEndOfFrameStampIsAllowedTheWholeReadout)
{
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.stampFlags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_TSTAMP_SRC_EOF;
        video_.driver = "some-csi-bridge";
        video_.controls = {{V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL}, {V4L2_CID_EXPOSURE_ABSOLUTE, 100}};
        video_.intervalNum = 1;
        video_.intervalDen = 30;
    }
    hal::V4l2Options o = opts("/dev/video0", 4);
    o.controls.exposureUs = 10000;
    o.stampDelayUs = 2000;
    hal::V4l2Camera cam(clock_, o, &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    EXPECT_NE(cam.describe().find("end of frame"), std::string::npos) << cam.describe();
    const int64_t litMs = clock_.monotonicMs() + 40;
    const int64_t L = nowNs() + 40000000;
    expose(L + 30000000, 1); // began at least 30 - 10 - 33 = -13 ms from L: maybe in the dark
    expose(L + 45000000, 2); // began at least 2 ms after L
    hal::CapturedFrame frame;
    const hal::Error e = cam.capture({litMs, 500}, &frame);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(frame.view.data[0], 2);
    EXPECT_EQ(frame.staleFrames, 1);
}

TEST_F(V4l2Mock, CaptureTimesOutWithoutBlocking)
{
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    hal::CapturedFrame frame;
    const int64_t t0 = clock_.monotonicMs();
    hal::Error e = cam.capture(150, &frame);
    const int64_t took = clock_.monotonicMs() - t0;
    EXPECT_EQ(e.code, hal::Errc::Timeout) << e.message;
    EXPECT_GE(took, 140);
    EXPECT_LT(took, 1000);
}

TEST_F(V4l2Mock, CaptureTimesOutEvenWithAManualClock)
{
    hal::ManualClock manual(5000); // does not move while the camera waits
    hal::V4l2Camera cam(manual, opts("/dev/video0", 2), &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    hal::CapturedFrame frame;
    EXPECT_EQ(cam.capture(100, &frame).code, hal::Errc::Timeout);
}

TEST_F(V4l2Mock, UnplugIsAnErrorAndCaptureResumesAfterReplug)
{
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    ASSERT_TRUE(cam.configure({hal::PixelFormat::YUYV, 640, 480}).ok());
    hal::CapturedFrame frame;
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.unplugged = true;
    }
    hal::Error e = cam.capture(200, &frame);
    EXPECT_EQ(e.code, hal::Errc::Closed) << e.message;
    EXPECT_NE(e.message.find("unplugged"), std::string::npos) << e.message;
    EXPECT_EQ(mapper_.mapped, 0); // everything released
    // Still gone: a clear error, no hang.
    e = cam.capture(200, &frame);
    EXPECT_FALSE(e.ok());
    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.unplugged = false;
        video_.streaming = false;
    }
    expose(nowNs() + 1000000000, 77);
    e = cam.capture(500, &frame);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(frame.view.data[0], 77);
}

TEST_F(V4l2Mock, NoCameraIsNotFound)
{
    hal::V4l2Camera cam(clock_, opts("/dev/video5", 2), &mapper_);
    hal::Error e = cam.configure({hal::PixelFormat::YUYV, 640, 480});
    EXPECT_EQ(e.code, hal::Errc::NotFound) << e.message;
    hal::CapturedFrame frame;
    EXPECT_EQ(cam.capture(10, &frame).code, hal::Errc::NotFound);
}

// The product-level bar: the camera unplugged while streaming shows as an error on the display
// and on serial, the program keeps going, and measuring resumes once it is plugged back in.
struct QuietTrigger final : hal::TriggerButton {
    hal::Result<size_t> readEdges(hal::ButtonEdge *, size_t) override { return {}; }
};
// The LED ring and the scene the fake camera sees: switched on, it has the camera expose the
// frames it is scripted to (by default one lit top to bottom); the frame with the ring off
// that each measurement starts with is exposed by the test.
struct PlainLed final : hal::LedRing {
    FakeVideo *video = nullptr;
    std::vector<FakeVideo::Frame> whenOn{{0, 180}}; // ns: after the switch
    bool on = false;
    hal::Error set(bool v) override
    {
        if (v && !on && video) {
            std::lock_guard<std::mutex> lock(video->m);
            for (FakeVideo::Frame f : whenOn)
                video->exposures.push_back({nowNs() + 1000000000 + f.ns, f.fill, f.bottomFill});
        }
        on = v;
        return {};
    }
    bool isOn() const override { return on; }
};
using test::RecordingSerial;
struct RecordingDisplay final : hal::Display {
    hal::MonoBitmap last;
    hal::Error show(const hal::MonoBitmap &p) override
    {
        last = p;
        return {};
    }
};

TEST_F(V4l2Mock, FirmwareReportsUnplugAndMeasuresAgainAfterReplug)
{
    char t[] = "/tmp/icacam-v4l2-fw-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 2), &mapper_);
    QuietTrigger trigger;
    PlainLed led;
    led.video = &video_;
    RecordingDisplay display;
    RecordingSerial serial;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir, 0).ok());
    fw::Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.0125;
    cfg.cameraMaxWidth = 640;
    cfg.cameraMaxHeight = 480;
    cfg.captureTimeoutMs = 300;
    cfg.journalImages = "none";
    friction::PaperModel model;
    fw::Device device({cam, trigger, led, display, serial, storage, clock_}, cfg, model);
    ASSERT_TRUE(device.start().ok());

    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.unplugged = true;
    }
    serial.in = "trigger\n";
    device.tick();
    EXPECT_NE(serial.out.find("\"code\":\"measurement_failed\""), std::string::npos) << serial.out;
    EXPECT_NE(serial.out.find("unplugged"), std::string::npos) << serial.out;
    EXPECT_EQ(fw::readRow(display.last, 0), "#1 error");
    EXPECT_NE(fw::readRow(display.last, 2).find("camera"), std::string::npos) << fw::readRow(display.last, 2);
    EXPECT_FALSE(led.on);

    {
        std::lock_guard<std::mutex> lock(video_.m);
        video_.unplugged = false;
        video_.streaming = false;
    }
    // The camera streams again: a frame proves it (a lost camera is ok again only then), one
    // more is the measurement's frame with the ring off.
    expose(nowNs() + 1000000000, 20);
    expose(nowNs() + 1000000000, 20);
    serial.out.clear();
    serial.in = "trigger\n";
    device.tick();
    // A frame was captured and measured (a blank frame: the vision finds no specimen, a
    // result, not a camera failure).
    EXPECT_EQ(serial.out.find("camera"), std::string::npos) << serial.out;
    EXPECT_NE(fw::readRow(display.last, 0).find("#2"), std::string::npos) << fw::readRow(display.last, 0);
    std::filesystem::remove_all(dir);
}

// The bar for a camera that is not there at start: a V4L2 node that does not exist. The
// device runs, says so on the display, in `hello` and in `status`, and measures once the
// node appears.
TEST_F(V4l2Mock, FirmwareStartsWithoutItsCameraAndMeasuresOnceTheNodeAppears)
{
    char t[] = "/tmp/icacam-v4l2-missing-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    hal::V4l2Camera cam(clock_, opts("/dev/video1", 2), &mapper_);
    QuietTrigger trigger;
    PlainLed led;
    led.video = &video_;
    RecordingDisplay display;
    RecordingSerial serial;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir, 0).ok());
    fw::Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.0125;
    cfg.cameraMaxWidth = 640;
    cfg.cameraMaxHeight = 480;
    cfg.captureTimeoutMs = 300;
    cfg.cameraRetryMs = 100;
    cfg.journalImages = "none";
    friction::PaperModel model;
    fw::Device device({cam, trigger, led, display, serial, storage, clock_}, cfg, model);
    ASSERT_TRUE(device.start().ok());
    const reading::FlatObject hello = serial.last("hello");
    ASSERT_TRUE(hello.find("camera")) << serial.out;
    EXPECT_EQ(hello.find("camera")->text, "missing");
    EXPECT_NE(hello.find("camera_problem")->text.find("/dev/video1"), std::string::npos);
    EXPECT_EQ(fw::readRow(display.last, 0), "icacam: no camera");
    EXPECT_NE(fw::readRow(display.last, 2).find("/dev/video1"), std::string::npos) << fw::readRow(display.last, 2);
    serial.in = "status\n";
    device.tick();
    EXPECT_EQ(serial.last("status").find("camera")->text, "missing");

    // The camera is plugged in: its node appears.
    GError *err = nullptr;
    const char *dev = "P: /devices/pci0000:00/usb1/1-2/1-2:1.0/video4linux/video1\n"
                      "N: video1\n"
                      "E: SUBSYSTEM=video4linux\n"
                      "E: DEVNAME=/dev/video1\n"
                      "A: dev=81:1\\n\n";
    ASSERT_TRUE(umockdev_testbed_add_from_string(bed_, dev, &err)) << (err ? err->message : "");
    ASSERT_TRUE(umockdev_testbed_attach_ioctl(bed_, "/dev/video1", handler_, &err)) << (err ? err->message : "");
    ::usleep(150000);
    serial.out.clear();
    device.tick();
    const reading::FlatObject back = serial.last("camera");
    ASSERT_TRUE(back.find("camera")) << serial.out;
    EXPECT_EQ(back.find("camera")->text, "ok");
    EXPECT_EQ(fw::readRow(display.last, 0), "icacam  ready");
    expose(nowNs() + 1000000000, 20); // the ring off
    serial.in = "trigger\n";
    device.tick();
    const reading::FlatObject r = serial.last("result");
    ASSERT_TRUE(r.find("source")) << serial.out;
    EXPECT_EQ(r.find("source")->text, "/dev/video1");
    ASSERT_TRUE(r.find("latency_us"));
    EXPECT_GE(r.find("latency_us")->number, 0);
    std::filesystem::remove_all(dir);
}

// The lit-frame check on the V4L2 path: the ring lights late, so the first frame after it was
// switched on is lit in its bottom half only (a webcam that buffered a frame exposed across
// the edge). It is refused and the next one, lit top to bottom, measured; a ring that never
// lights the whole frame ends in "LED ring not lit".
TEST_F(V4l2Mock, FirmwareRefusesAFrameTheRingLitInPart)
{
    char t[] = "/tmp/icacam-v4l2-lit-XXXXXX";
    const std::string dir = ::mkdtemp(t);
    hal::V4l2Camera cam(clock_, opts("/dev/video0", 3), &mapper_);
    QuietTrigger trigger;
    PlainLed led;
    led.video = &video_;
    led.whenOn = {{0, 20, 180}, {1000, 180}};
    RecordingDisplay display;
    RecordingSerial serial;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir, 0).ok());
    fw::Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.0125;
    cfg.cameraMaxWidth = 640;
    cfg.cameraMaxHeight = 480;
    cfg.captureTimeoutMs = 300;
    cfg.journalImages = "none";
    friction::PaperModel model;
    fw::Device device({cam, trigger, led, display, serial, storage, clock_}, cfg, model);
    ASSERT_TRUE(device.start().ok());
    expose(nowNs() + 1000000000, 20); // the ring off
    serial.in = "trigger\n";
    device.tick();
    reading::FlatObject r = serial.last("result");
    ASSERT_TRUE(r.find("lit")) << serial.out;
    EXPECT_EQ(r.find("lit")->text, "lit");
    EXPECT_EQ(r.find("unlit_frames")->number, 1);
    EXPECT_EQ(serial.out.find("LED ring not lit"), std::string::npos) << serial.out;

    led.whenOn = {{0, 20, 180}, {1000, 20, 180}, {2000, 20, 180}};
    expose(nowNs() + 1000000000, 20);
    serial.out.clear();
    serial.in = "trigger\n";
    device.tick();
    r = serial.last("result");
    ASSERT_TRUE(r.find("lit")) << serial.out;
    EXPECT_EQ(r.find("lit")->text, "partly_lit");
    EXPECT_EQ(r.find("status")->text, "error");
    const reading::FlatObject e = serial.last("error");
    ASSERT_TRUE(e.find("message")) << serial.out;
    EXPECT_EQ(e.find("message")->text.rfind("LED ring not lit: lit at the bottom only", 0), 0u)
        << e.find("message")->text;
    EXPECT_FALSE(led.on);
    std::filesystem::remove_all(dir);
}

} // namespace

int main(int argc, char **argv)
{
    return icacam::test::runUnderUmockdev(argc, argv, "v4l2_umockdev_test");
}
