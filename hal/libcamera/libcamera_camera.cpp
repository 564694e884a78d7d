// libcamera backend. Version points (PLATFORM.md "Library versions to support"):
//  * 0.5+: manual exposure and gain are ignored unless ExposureTimeMode / AnalogueGainMode
//    are set to Manual.
//  * 0.6: FrameBuffer::planes() is a Span (only iterated and indexed here: no #if needed);
//    addBuffer's fence argument changes type (not passed here).
//  * 0.7: Request::metadata() is const (only FrameMetadata is read here).
// libcamera does not throw; its errors are negative errno values turned into hal::Error.
#include "hal/libcamera/libcamera_camera.h"

#include <libcamera/camera.h>
#include <libcamera/camera_manager.h>
#include <libcamera/control_ids.h>
#include <libcamera/controls.h>
#include <libcamera/formats.h>
#include <libcamera/framebuffer.h>
#include <libcamera/framebuffer_allocator.h>
#include <libcamera/request.h>
#include <libcamera/stream.h>
#include <libcamera/version.h>
#include <sys/mman.h>
#include <time.h>

#include <array>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <vector>

#define ICACAM_LIBCAMERA_AT_LEAST(maj, min)                                                        \
    (LIBCAMERA_VERSION_MAJOR > (maj) || (LIBCAMERA_VERSION_MAJOR == (maj) && LIBCAMERA_VERSION_MINOR >= (min)))

namespace icacam::hal {

namespace lc = libcamera;

namespace {

int64_t monotonicNs()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

bool lumaFormat(const lc::PixelFormat &pf, vision::PixelFormat *out)
{
    if (pf == lc::formats::R8) *out = vision::PixelFormat::Grey8;
    else if (pf == lc::formats::NV12) *out = vision::PixelFormat::NV12;
    else if (pf == lc::formats::YUV420) *out = vision::PixelFormat::YUV420;
    else if (pf == lc::formats::YUYV) *out = vision::PixelFormat::YUYV;
    else return false;
    return true;
}

// One mapped dmabuf region (RAII, STYLE.md §11): plane 0 of a frame buffer.
struct Mapping {
    void *base = nullptr;
    size_t length = 0;
    const uint8_t *luma = nullptr;
    size_t lumaBytes = 0;
    Mapping() = default;
    Mapping(const Mapping &) = delete;
    Mapping &operator=(const Mapping &) = delete;
    ~Mapping()
    {
        if (base) ::munmap(base, length);
    }
};

} // namespace

struct LibcameraCamera::Session {
    lc::CameraManager manager;
    std::shared_ptr<lc::Camera> camera;
    bool acquired = false, started = false;
    std::unique_ptr<lc::CameraConfiguration> config;
    std::unique_ptr<lc::FrameBufferAllocator> allocator;
    lc::Stream *stream = nullptr;
    std::vector<std::unique_ptr<lc::Request>> requests;
    std::vector<std::unique_ptr<Mapping>> maps; // by request cookie
    vision::PixelFormat format = vision::PixelFormat::Grey8;
    int width = 0, height = 0, stride = 0;

    std::mutex m;
    std::condition_variable cv;
    std::vector<lc::Request *> done; // completed, not yet looked at (capacity = requests)
    lc::Request *held = nullptr;     // handed out by the last capture()
    bool gone = false;

    // Called on libcamera's thread: only records the request (no allocation: reserved).
    void onCompleted(lc::Request *r)
    {
        if (r->status() == lc::Request::RequestCancelled) return;
        std::lock_guard<std::mutex> lock(m);
        done.push_back(r);
        cv.notify_one();
    }
    void onDisconnected()
    {
        std::lock_guard<std::mutex> lock(m);
        gone = true;
        cv.notify_one();
    }
    ~Session()
    {
        if (started) camera->stop();
        if (camera) {
            camera->requestCompleted.disconnect(this);
            camera->disconnected.disconnect(this);
        }
        requests.clear();
        maps.clear();
        allocator.reset();
        if (acquired) camera->release();
        camera.reset();
        manager.stop();
    }
};

LibcameraCamera::LibcameraCamera(const Clock &clock, LibcameraOptions options)
    : clock_(clock), options_(std::move(options))
{
}

LibcameraCamera::~LibcameraCamera() { stop(); }

void LibcameraCamera::stop() { session_.reset(); }

Error LibcameraCamera::configure(const CameraFormat &fmt)
{
    if (fmt.maxWidth <= 0 || fmt.maxHeight <= 0)
        return Error::make(Errc::Invalid, "camera: maximum frame size must be positive");
    stop();
    wanted_ = fmt;
    configured_ = true;

    auto s = std::make_unique<Session>();
    if (int r = s->manager.start(); r < 0)
        return Error::make(Errc::Io, std::string("libcamera: camera manager: ") + std::strerror(-r));
    auto cams = s->manager.cameras();
    if (cams.empty()) return Error::make(Errc::NotFound, "libcamera: no camera found");
    s->camera = options_.cameraId.empty() ? cams.front() : s->manager.get(options_.cameraId);
    if (!s->camera) return Error::make(Errc::NotFound, "libcamera: no camera '" + options_.cameraId + "'");
    if (s->camera->acquire() < 0) return Error::make(Errc::Io, "libcamera: camera in use by another program");
    s->acquired = true;

    // A still configuration, kept streaming: each trigger then costs one frame.
    s->config = s->camera->generateConfiguration({lc::StreamRole::StillCapture});
    if (!s->config || s->config->empty()) return Error::make(Errc::BadFormat, "libcamera: no still configuration");
    lc::StreamConfiguration &sc = s->config->at(0);
    const lc::PixelFormat prefer[] = {fmt.format == vision::PixelFormat::Grey8 ? lc::formats::R8 : lc::formats::NV12,
                                      lc::formats::R8, lc::formats::NV12, lc::formats::YUV420};
    bool ok = false;
    for (const lc::PixelFormat &pf : prefer) {
        sc.pixelFormat = pf;
        sc.size = lc::Size(unsigned(fmt.maxWidth), unsigned(fmt.maxHeight));
        sc.bufferCount = unsigned(options_.bufferCount);
        const auto status = s->config->validate();
        if (status != lc::CameraConfiguration::Invalid && lumaFormat(sc.pixelFormat, &s->format)) {
            ok = true;
            break;
        }
    }
    if (!ok) return Error::make(Errc::BadFormat, "libcamera: no luma format (R8, NV12, YUV420) offered");
    if (int(sc.size.width) > fmt.maxWidth || int(sc.size.height) > fmt.maxHeight)
        return Error::make(Errc::TooLarge, "libcamera: sensor mode " + sc.size.toString() + " above the maximum");
    if (int r = s->camera->configure(s->config.get()); r < 0)
        return Error::make(Errc::Io, std::string("libcamera: configure: ") + std::strerror(-r));
    s->stream = sc.stream();
    s->width = int(sc.size.width);
    s->height = int(sc.size.height);
    s->stride = int(sc.stride);

    // Buffers, their mappings and one request per buffer: all allocated here, once.
    s->allocator = std::make_unique<lc::FrameBufferAllocator>(s->camera);
    if (s->allocator->allocate(s->stream) < 0) return Error::make(Errc::Io, "libcamera: buffer allocation failed");
    const auto &buffers = s->allocator->buffers(s->stream);
    s->done.reserve(buffers.size());
    for (size_t i = 0; i < buffers.size(); ++i) {
        lc::FrameBuffer *fb = buffers[i].get();
        const auto &plane = fb->planes()[0];
        auto map = std::make_unique<Mapping>();
        map->length = size_t(plane.offset) + plane.length;
        void *p = ::mmap(nullptr, map->length, PROT_READ, MAP_SHARED, plane.fd.get(), 0);
        if (p == MAP_FAILED) return Error::make(Errc::Io, std::string("libcamera: mmap: ") + std::strerror(errno));
        map->base = p;
        map->luma = static_cast<const uint8_t *>(p) + plane.offset;
        map->lumaBytes = 0;
        for (const auto &pl : fb->planes()) map->lumaBytes += pl.length; // chroma follows luma
        auto req = s->camera->createRequest(uint64_t(i));
        if (!req || req->addBuffer(s->stream, fb) < 0) return Error::make(Errc::Io, "libcamera: request setup failed");
        s->maps.push_back(std::move(map));
        s->requests.push_back(std::move(req));
    }

    // Measurement needs the same brightness every shot: fixed exposure and gain, AWB off
    // with locked colour gains.
    lc::ControlList controls(lc::controls::controls);
    controls.set(lc::controls::AeEnable, false);
#if ICACAM_LIBCAMERA_AT_LEAST(0, 5)
    controls.set(lc::controls::ExposureTimeMode, lc::controls::ExposureTimeModeManual);
    controls.set(lc::controls::AnalogueGainMode, lc::controls::AnalogueGainModeManual);
#endif
    controls.set(lc::controls::ExposureTime, int32_t(options_.exposureUs));
    controls.set(lc::controls::AnalogueGain, options_.analogueGain);
    controls.set(lc::controls::AwbEnable, false);
    const std::array<float, 2> gains{options_.redGain, options_.blueGain};
    controls.set(lc::controls::ColourGains, lc::Span<const float, 2>(gains));

    s->camera->requestCompleted.connect(s.get(), &Session::onCompleted);
    s->camera->disconnected.connect(s.get(), &Session::onDisconnected);
    if (int r = s->camera->start(&controls); r < 0)
        return Error::make(Errc::Io, std::string("libcamera: start: ") + std::strerror(-r));
    s->started = true;
    for (auto &req : s->requests)
        if (s->camera->queueRequest(req.get()) < 0) return Error::make(Errc::Io, "libcamera: queueRequest failed");
    session_ = std::move(s);
    return {};
}

Error LibcameraCamera::capture(int timeoutMs, CapturedFrame *out)
{
    if (!configured_) return Error::make(Errc::Invalid, "camera: not configured");
    if (!session_)
        if (Error e = configure(wanted_); !e.ok()) return e;
    Session &s = *session_;
    const int64_t startNs = monotonicNs();
    auto requeue = [&s](lc::Request *r) {
        r->reuse(lc::Request::ReuseBuffers);
        return s.camera->queueRequest(r) >= 0;
    };
    std::unique_lock<std::mutex> lock(s.m);
    if (s.held && !requeue(std::exchange(s.held, nullptr))) return Error::make(Errc::Io, "libcamera: requeue failed");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
    for (;;) {
        if (s.gone) {
            lock.unlock();
            stop(); // the next capture() looks for the camera again
            return Error::make(Errc::Closed, "libcamera: camera disconnected");
        }
        while (!s.done.empty()) {
            lc::Request *r = s.done.front();
            s.done.erase(s.done.begin());
            lc::FrameBuffer *fb = r->buffers().begin()->second;
            const lc::FrameMetadata &md = fb->metadata();
            // The first frame exposed after the trigger, never a stale one.
            if (r->status() != lc::Request::RequestComplete || md.status != lc::FrameMetadata::FrameSuccess ||
                int64_t(md.timestamp) < startNs) {
                if (!requeue(r)) return Error::make(Errc::Io, "libcamera: requeue failed");
                continue;
            }
            s.held = r;
            const Mapping &map = *s.maps[size_t(r->cookie())];
            out->view = {s.format, map.luma, s.width, s.height, s.stride, map.lumaBytes};
            out->timestampMs = clock_.monotonicMs() - (monotonicNs() - int64_t(md.timestamp)) / 1000000;
            out->source = "libcamera:" + s.camera->id();
            return {};
        }
        if (s.cv.wait_until(lock, deadline) == std::cv_status::timeout && s.done.empty() && !s.gone)
            return Error::make(Errc::Timeout, "libcamera: no frame within " + std::to_string(timeoutMs) + " ms");
    }
}

} // namespace icacam::hal
