// libcamera backend. Version points (PLATFORM.md "Library versions to support"):
//  * 0.2+: CameraConfiguration::sensorConfig names the sensor mode; before, a raw stream.
//  * 0.5+: manual exposure and gain are ignored unless ExposureTimeMode / AnalogueGainMode
//    are set to Manual.
//  * 0.6: FrameBuffer::planes() is a Span (only iterated and indexed here: no #if needed);
//    addBuffer's fence argument changes type (not passed here).
//  * 0.7: Request::metadata() is const (only FrameMetadata is read here).
//  * 0.6+: string properties may be string_views: the model is copied into a std::string.
// libcamera does not throw; its errors are negative errno values turned into hal::Error.
#include "hal/libcamera/libcamera_camera.h"

#include <libcamera/camera.h>
#include <libcamera/camera_manager.h>
#include <libcamera/control_ids.h>
#include <libcamera/controls.h>
#include <libcamera/formats.h>
#include <libcamera/framebuffer.h>
#include <libcamera/framebuffer_allocator.h>
#include <libcamera/property_ids.h>
#include <libcamera/request.h>
#include <libcamera/stream.h>
#include <libcamera/version.h>
#include <sys/mman.h>
#include <time.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <type_traits>
#include <vector>

#include "hal/fresh_frame.h"
#include "hal/libcamera/control_settle.h"
#include "hal/libcamera/sensor_mode.h"
#include "hal/libcamera/tuning.h"

#define ICACAM_LIBCAMERA_AT_LEAST(maj, min)                                                                            \
    (LIBCAMERA_VERSION_MAJOR > (maj) || (LIBCAMERA_VERSION_MAJOR == (maj) && LIBCAMERA_VERSION_MINOR >= (min)))

namespace icacam::hal {

namespace lc = libcamera;

namespace {

std::string modelOf(const lc::Camera &cam)
{
    const auto model = cam.properties().get(lc::properties::Model);
    return model ? std::string(*model) : std::string();
}

// The camera the options name: an exact id, else a part of the sensor's model name.
std::shared_ptr<lc::Camera> pickCamera(lc::CameraManager &manager, const std::string &want)
{
    auto cams = manager.cameras();
    if (cams.empty()) return nullptr;
    if (want.empty()) return cams.front();
    if (auto byId = manager.get(want)) return byId;
    for (const auto &c : cams)
        if (modelOf(*c).find(want) != std::string::npos) return c;
    return nullptr;
}

// The largest size the pipeline lists for this format that fits the maximum and is not
// larger than the sensor's pixel array: the ISP can scale up to its buffer limit, which
// adds no detail and costs memory (a 4096 × 3072 buffer is ~19 MB of CMA).
lc::Size sensorSize(const lc::Camera &cam, const lc::StreamConfiguration &sc, const lc::PixelFormat &pf, int maxW,
                    int maxH)
{
    if (const auto array = cam.properties().get(lc::properties::PixelArraySize)) {
        maxW = std::min(maxW, int(array->width));
        maxH = std::min(maxH, int(array->height));
    }
    lc::Size best;
    for (const lc::Size &sz : sc.formats().sizes(pf))
        if (int(sz.width) <= maxW && int(sz.height) <= maxH &&
            uint64_t(sz.width) * sz.height > uint64_t(best.width) * best.height)
            best = sz;
    if (best.width == 0 && maxW > 0 && maxH > 0) best = lc::Size(unsigned(maxW), unsigned(maxH));
    return best;
}

bool supports(const lc::Camera &cam, const lc::ControlId &id)
{
    return cam.controls().find(id.id()) != cam.controls().end();
}

std::string fmtNum(double v)
{
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

bool lumaFormat(const lc::PixelFormat &pf, PixelFormat *out)
{
    if (pf == lc::formats::R8)
        *out = PixelFormat::Grey8;
    else if (pf == lc::formats::NV12)
        *out = PixelFormat::NV12;
    else if (pf == lc::formats::YUV420)
        *out = PixelFormat::YUV420;
    else if (pf == lc::formats::YUYV)
        *out = PixelFormat::YUYV;
    else
        return false;
    return true;
}

// The sensor's modes as the pipeline lists them for a raw stream: each raw pixel format
// (one per bit depth) with its sizes, which on a Raspberry Pi are the sensor driver's own
// (generateConfiguration(Raw) translates the sensor's media-bus formats, pipeline_base.cpp).
struct RawMode {
    SensorMode mode;
    lc::PixelFormat format;
};

std::vector<RawMode> rawModes(lc::Camera &cam)
{
    std::vector<RawMode> out;
    const std::vector<lc::StreamRole> roles{lc::StreamRole::Raw};
    const auto config = cam.generateConfiguration(roles);
    if (!config || config->empty()) return out;
    const lc::StreamFormats &formats = config->at(0).formats();
    for (const lc::PixelFormat &pf : formats.pixelformats()) {
        const int depth = rawBitDepth(pf.toString());
        if (depth == 0) continue;
        for (const lc::Size &sz : formats.sizes(pf)) {
            const SensorMode m{int(sz.width), int(sz.height), depth};
            bool seen = false;
            for (const RawMode &o : out)
                seen = seen || (o.mode.width == m.width && o.mode.height == m.height && o.mode.bitDepth == depth);
            if (!seen) out.push_back({m, pf});
        }
    }
    return out;
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
    PixelFormat format = PixelFormat::Grey8;
    int width = 0, height = 0, stride = 0;

    std::mutex m;
    std::condition_variable cv;
    std::vector<lc::Request *> done; // completed, not yet looked at (capacity = requests)
    lc::Request *held = nullptr;     // handed out by the last capture()
    bool gone = false;
    // Controls for the next request queued (setControls, autofocus), and what the last frame
    // handed out reported of them. Touched by the calling thread only.
    lc::ControlList pending{lc::controls::controls};
    int afState = -1;
    float lensPosition = -1;
    // The last setControls() until a frame shows it (control_settle.h): each request's
    // generation when it was last queued (a request queued before the change cannot carry
    // it), and how many frames after it may still not show it before one is taken anyway.
    ControlChange change;
    bool changing = false;
    int changeFramesLeft = 0;
    uint64_t generation = 0;
    std::vector<uint64_t> queuedIn; // by request cookie, sized in configure()

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
{}

LibcameraCamera::~LibcameraCamera()
{
    stop();
    if (!tuningDir_.empty()) {
        std::error_code ec;
        std::filesystem::remove_all(tuningDir_, ec); // the override is this process's only
    }
}

void LibcameraCamera::stop()
{
    session_.reset();
}

// Three ways to put the sensor in the chosen mode, best first: the sensor configuration
// (libcamera 0.2+, what rpicam-still sets beside its raw stream), a raw stream at the mode's
// size (the pipeline takes the largest raw stream's size for the sensor, pipeline_base.cpp
// validate(); requests carry no raw buffer, so the pipeline fills its own), or only the
// processed stream at the mode's size (pipelines without raw modes). Each is validated; the
// first that gives a luma format at the asked size is kept.
Error LibcameraCamera::configureStreams(Session &s, const CameraFormat &fmt)
{
    const std::vector<RawMode> modes = rawModes(*s.camera);
    mode_.sensorModes.clear();
    for (const RawMode &m : modes) mode_.sensorModes.push_back(m.mode);
    lc::Size out(unsigned(options_.width), unsigned(options_.height));
    const RawMode *raw = nullptr;
    if (!modes.empty()) {
        mode_.choice =
            chooseSensorMode(mode_.sensorModes, fmt.maxWidth, fmt.maxHeight, options_.width, options_.height);
        if (!mode_.choice.found)
            return Error::make(Errc::TooLarge, "libcamera: camera.width x height " + std::to_string(options_.width) +
                                                   "x" + std::to_string(options_.height) + " above the maximum");
        for (const RawMode &m : modes)
            if (m.mode.width == mode_.choice.mode.width && m.mode.height == mode_.choice.mode.height &&
                m.mode.bitDepth == mode_.choice.mode.bitDepth)
                raw = &m;
        out = lc::Size(unsigned(mode_.choice.outWidth), unsigned(mode_.choice.outHeight));
    }

    enum class NamedBy { SensorConfig, RawStream, StreamSize };
    std::vector<NamedBy> ways;
#if ICACAM_LIBCAMERA_AT_LEAST(0, 2)
    if (raw) ways.push_back(NamedBy::SensorConfig);
#endif
    if (raw) ways.push_back(NamedBy::RawStream);
    ways.push_back(NamedBy::StreamSize);
    // R8 is a raw format on a Raspberry Pi (isRaw, pipeline_base.cpp): a processed stream
    // asked for it turns into a second raw stream. Only a pipeline without raw modes may
    // offer it processed.
    std::vector<lc::PixelFormat> prefer;
    if (modes.empty() && fmt.format == PixelFormat::Grey8) prefer.push_back(lc::formats::R8);
    prefer.push_back(lc::formats::NV12);
    prefer.push_back(lc::formats::YUV420);
    if (modes.empty()) prefer.push_back(lc::formats::R8);

    for (NamedBy way : ways) {
        std::vector<lc::StreamRole> roles{lc::StreamRole::StillCapture};
        if (way == NamedBy::RawStream) roles.push_back(lc::StreamRole::Raw);
        for (const lc::PixelFormat &pf : prefer) {
            s.config = s.camera->generateConfiguration(roles);
            if (!s.config || s.config->size() != roles.size()) break;
            lc::StreamConfiguration &sc = s.config->at(0);
            sc.pixelFormat = pf;
            sc.size = out.width ? out : sensorSize(*s.camera, sc, pf, fmt.maxWidth, fmt.maxHeight);
            if (sc.size.width == 0) sc.size = lc::Size(unsigned(fmt.maxWidth), unsigned(fmt.maxHeight));
            sc.bufferCount = unsigned(options_.bufferCount);
            if (way == NamedBy::RawStream) {
                lc::StreamConfiguration &rc = s.config->at(1);
                rc.pixelFormat = raw->format;
                rc.size = lc::Size(unsigned(raw->mode.width), unsigned(raw->mode.height));
                // The Pi 5 pipeline allocates max(2, 4 - this) raw buffers of its own
                // (PipelineHandlerPiSP::allocateBuffers); none of the application's are used.
                rc.bufferCount = 1;
            }
#if ICACAM_LIBCAMERA_AT_LEAST(0, 2)
            if (way == NamedBy::SensorConfig) {
                s.config->sensorConfig = lc::SensorConfiguration();
                s.config->sensorConfig->outputSize = lc::Size(unsigned(raw->mode.width), unsigned(raw->mode.height));
                s.config->sensorConfig->bitDepth = unsigned(raw->mode.bitDepth);
            }
#endif
            const lc::Size asked = sc.size;
            if (s.config->validate() == lc::CameraConfiguration::Invalid) continue;
            if (!lumaFormat(sc.pixelFormat, &s.format)) continue;
            if (int(sc.size.width) > fmt.maxWidth || int(sc.size.height) > fmt.maxHeight)
                return Error::make(Errc::TooLarge, "libcamera: stream " + sc.size.toString() + " above the maximum " +
                                                       std::to_string(fmt.maxWidth) + "x" +
                                                       std::to_string(fmt.maxHeight));
            mode_.namedBy = way == NamedBy::SensorConfig ? "sensor configuration"
                            : way == NamedBy::RawStream  ? "raw stream"
                                                         : "stream size";
            if (sc.size != asked) mode_.namedBy += ", size adjusted from " + asked.toString();
            return {};
        }
    }
    s.config.reset();
    return Error::make(Errc::BadFormat, "libcamera: no luma format (NV12, YUV420, R8) offered at " + out.toString());
}

Error LibcameraCamera::openSession(std::unique_ptr<Session> *out)
{
    auto s = std::make_unique<Session>();
    if (int r = s->manager.start(); r < 0)
        return Error::make(Errc::Io, std::string("libcamera: camera manager: ") + std::strerror(-r));
    if (s->manager.cameras().empty()) return Error::make(Errc::NotFound, "libcamera: no camera found");
    s->camera = pickCamera(s->manager, options_.camera);
    if (!s->camera)
        return Error::make(Errc::NotFound, "libcamera: no camera '" + options_.camera + "' (by id or model)");
    if (s->camera->acquire() < 0) return Error::make(Errc::Io, "libcamera: camera in use by another program");
    s->acquired = true;
    *out = std::move(s);
    return {};
}

// The tuning file is read when the camera manager starts (the pipeline loads the IPA as it
// registers the camera: CameraData::loadIPA, pipeline_base.cpp), so the environment is set
// before a manager exists; the fixed-tone override needs the sensor's model, so the first
// configure() looks at the camera, writes the override and starts the manager again.
Error LibcameraCamera::prepareTuning(const std::string &model, bool *restart)
{
    *restart = false;
    if (options_.tuning == "system") {
        tuningNote_ = "tuning: libcamera's file for " + model;
        return {};
    }
    if (!options_.tuning.empty()) { // set before the first manager started (configure())
        tuningNote_ = "tuning: " + options_.tuning;
        return {};
    }
    if (const char *forced = std::getenv("LIBCAMERA_RPI_TUNING_FILE"); forced && *forced) {
        // libcamera takes this over every search path (ipaConfigurationFile, ipa_proxy.cpp).
        tuningNote_ = std::string("tuning: LIBCAMERA_RPI_TUNING_FILE=") + forced + " (not the fixed-tone override)";
        return {};
    }
    if (model == tuningModel_) return {};
    if (tuningDir_.empty()) {
        std::string base = options_.tuningDir;
        if (base.empty()) {
            const char *runtime = std::getenv("RUNTIME_DIRECTORY"); // systemd's RuntimeDirectory=
            base = runtime && *runtime ? std::string(runtime).substr(0, std::string(runtime).find(':')) : "/tmp";
        }
        std::string tmpl = base + "/icacam-tuning-XXXXXX";
        if (!::mkdtemp(tmpl.data())) {
            tuningModel_ = model;
            tuningNote_ = "tuning: no folder for the override in " + base + " (" + std::strerror(errno) +
                          "), adaptive contrast as libcamera's file sets";
            return {};
        }
        tuningDir_ = tmpl;
    }
    TuningOverride written, mono; // a mono sensor's file is <model>_mono.json (loadIPA)
    Error e = writeFixedToneTuning(kIpaDataDirs, model, tuningDir_, options_.toneGamma, &written);
    if (e.ok()) e = writeFixedToneTuning(kIpaDataDirs, model + "_mono", tuningDir_, options_.toneGamma, &mono);
    tuningModel_ = model;
    if (!e.ok()) {
        // The camera still works with libcamera's own file: measure, and say so everywhere.
        tuningNote_ = "tuning: override failed (" + e.message + "), adaptive contrast as libcamera's file sets";
        return {};
    }
    if (written.files + mono.files == 0) {
        tuningNote_ = "tuning: no Raspberry Pi tuning file for " + model + " (tone curve as the pipeline sets it)";
        return {};
    }
    const char *old = std::getenv("LIBCAMERA_IPA_CONFIG_PATH");
    std::string path = tuningDir_;
    if (old && *old && std::string(old).find(tuningDir_) == std::string::npos) path += std::string(":") + old;
    ::setenv("LIBCAMERA_IPA_CONFIG_PATH", path.c_str(), 1);
    const std::string &from = written.files ? written.source : mono.source;
    char curve[48];
    std::snprintf(curve, sizeof curve, options_.toneGamma == 1 ? "a linear tone curve" : "tone curve linear^(1/%g)",
                  options_.toneGamma);
    tuningNote_ = "tuning: " + from.substr(from.rfind('/') + 1) + " with adaptive contrast off and " + curve;
    *restart = true;
    return {};
}

Error LibcameraCamera::configure(const CameraFormat &fmt)
{
    if (fmt.maxWidth <= 0 || fmt.maxHeight <= 0)
        return Error::make(Errc::Invalid, "camera: maximum frame size must be positive");
    stop();
    wanted_ = fmt;
    configured_ = true;
    mode_ = {};
    if (!options_.tuning.empty() && options_.tuning != "system")
        ::setenv("LIBCAMERA_RPI_TUNING_FILE", options_.tuning.c_str(), 1);

    std::unique_ptr<Session> s;
    if (Error e = openSession(&s); !e.ok()) return e;
    bool restart = false;
    if (Error e = prepareTuning(modelOf(*s->camera), &restart); !e.ok()) return e;
    if (restart) {
        s.reset(); // a new manager reads the tuning override when it registers the camera
        if (Error e = openSession(&s); !e.ok()) return e;
    }
    if (Error e = configureStreams(*s, fmt); !e.ok()) return e;
    if (int r = s->camera->configure(s->config.get()); r < 0)
        return Error::make(Errc::Io, std::string("libcamera: configure: ") + std::strerror(-r));
    lc::StreamConfiguration &sc = s->config->at(0);
    s->stream = sc.stream();
    s->width = int(sc.size.width);
    s->height = int(sc.size.height);
    s->stride = int(sc.stride);
    mode_.model = modelOf(*s->camera);
    mode_.width = s->width;
    mode_.height = s->height;
    mode_.pixelFormat = sc.pixelFormat.toString();
    mode_.tuning = tuningNote_;

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
    s->queuedIn.assign(s->requests.size(), 0);

    // Measurement needs the same picture every shot: fixed exposure and gain, AWB off with
    // locked colour gains, the lens held where it was focused, and the ISP's sharpening
    // (it shifts edges) and noise reduction as configured.
    const CameraControls &want = options_.controls;
    lc::ControlList controls(lc::controls::controls);
    controls.set(lc::controls::AeEnable, false);
#if ICACAM_LIBCAMERA_AT_LEAST(0, 5)
    controls.set(lc::controls::ExposureTimeMode, lc::controls::ExposureTimeModeManual);
    controls.set(lc::controls::AnalogueGainMode, lc::controls::AnalogueGainModeManual);
#endif
    if (want.exposureUs >= 0) controls.set(lc::controls::ExposureTime, int32_t(want.exposureUs));
    if (want.analogueGain >= 0) controls.set(lc::controls::AnalogueGain, float(want.analogueGain));
    if (want.redGain >= 0 && want.blueGain >= 0) {
        controls.set(lc::controls::AwbEnable, false);
        const std::array<float, 2> gains{float(want.redGain), float(want.blueGain)};
        controls.set(lc::controls::ColourGains, lc::Span<const float, 2>(gains));
    }
    std::string notes;
    if (want.lensPosition >= 0) {
        if (supports(*s->camera, lc::controls::AfMode) && supports(*s->camera, lc::controls::LensPosition)) {
            controls.set(lc::controls::AfMode, lc::controls::AfModeManual);
            controls.set(lc::controls::LensPosition, float(want.lensPosition));
        } else {
            notes += ", no lens control (fixed focus)";
        }
    }
    if (want.sharpness >= 0 && supports(*s->camera, lc::controls::Sharpness))
        controls.set(lc::controls::Sharpness, float(want.sharpness));
    if (want.noiseReduction >= 0 && supports(*s->camera, lc::controls::draft::NoiseReductionMode))
        controls.set(lc::controls::draft::NoiseReductionMode, int32_t(want.noiseReduction));

    s->camera->requestCompleted.connect(s.get(), &Session::onCompleted);
    s->camera->disconnected.connect(s.get(), &Session::onDisconnected);
    if (int r = s->camera->start(&controls); r < 0)
        return Error::make(Errc::Io, std::string("libcamera: start: ") + std::strerror(-r));
    s->started = true;
    for (auto &req : s->requests)
        if (s->camera->queueRequest(req.get()) < 0) return Error::make(Errc::Io, "libcamera: queueRequest failed");
    // The mode, the stream and the tuning go into `status` (describe()) and, shorter, into
    // every frame's `source`, which the journal keeps with each result.
    std::string mode = "sensor mode ";
    if (mode_.choice.found)
        mode += std::to_string(mode_.choice.mode.width) + "x" + std::to_string(mode_.choice.mode.height) + " " +
                std::to_string(mode_.choice.mode.bitDepth) + "-bit by " + mode_.namedBy +
                (mode_.choice.scaled ? ", scaled by the ISP" : "");
    else
        mode += "unlisted, by " + mode_.namedBy;
    description_ = "libcamera " + s->camera->id() + " " + modelOf(*s->camera) + " " + sc.size.toString() + " " +
                   sc.pixelFormat.toString() + " (" + mode + "), " + tuningNote_;
    notes_ = notes;
    source_ = "libcamera:" + modelOf(*s->camera) + " " + sc.size.toString();
    if (mode_.choice.found)
        source_ += " mode " + std::to_string(mode_.choice.mode.width) + "x" + std::to_string(mode_.choice.mode.height) +
                   "/" + std::to_string(mode_.choice.mode.bitDepth);
    source_ += tuningNote_.find("adaptive contrast off") != std::string::npos ? " tone fixed" : " tone default";
    session_ = std::move(s);
    return {};
}

std::string LibcameraCamera::describe() const
{
    if (!session_) return description_;
    return description_ + ", exposure " + std::to_string(options_.controls.exposureUs) + " us, gain " +
           fmtNum(options_.controls.analogueGain) + notes_;
}

Error LibcameraCamera::capture(const CaptureRequest &req, CapturedFrame *out)
{
    if (!configured_) return Error::make(Errc::Invalid, "camera: not configured");
    if (!session_)
        if (Error e = configure(wanted_); !e.ok()) return e;
    Session &s = *session_;
    const int timeoutMs = req.timeoutMs;
    const int64_t notBeforeNs = notBeforeOnMonotonicNs(clock_, req.notBeforeMs);
    auto requeue = [&s](lc::Request *r) {
        r->reuse(lc::Request::ReuseBuffers); // clears the request's controls too
        if (!s.pending.empty()) {
            r->controls().merge(s.pending);
            s.pending.clear();
        }
        s.queuedIn[size_t(r->cookie())] = s.generation;
        return s.camera->queueRequest(r) >= 0;
    };
    int stale = 0;
    std::unique_lock<std::mutex> lock(s.m);
    if (s.held && !requeue(std::exchange(s.held, nullptr))) return Error::make(Errc::Io, "libcamera: requeue failed");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
    for (;;) {
        if (s.gone) {
            lock.unlock();
            stop(); // the next capture() looks for the camera again
            description_ = "libcamera: camera disconnected";
            return Error::make(Errc::Closed, "libcamera: camera disconnected");
        }
        while (!s.done.empty()) {
            lc::Request *r = s.done.front();
            s.done.erase(s.done.begin());
            lc::FrameBuffer *fb = r->buffers().begin()->second;
            const lc::FrameMetadata &md = fb->metadata();
            if (r->status() != lc::Request::RequestComplete || md.status != lc::FrameMetadata::FrameSuccess) {
                if (!requeue(r)) return Error::make(Errc::Io, "libcamera: requeue failed");
                continue;
            }
            // The exposure's start from the sensor's own timestamp (fresh_frame.h); a
            // pipeline that reports neither falls back to the buffer's, with the asked exposure.
            const auto &meta = r->metadata();
            const auto sensorNs = meta.get(lc::controls::SensorTimestamp);
            const auto exposureUs = meta.get(lc::controls::ExposureTime);
            FrameStamp stamp;
            stamp.stampNs = sensorNs ? *sensorNs : int64_t(md.timestamp);
            stamp.exposureNs = int64_t(exposureUs ? *exposureUs : std::max(options_.controls.exposureUs, 0)) * 1000;
            if (!exposedAfter(stamp, notBeforeNs)) {
                ++stale;
                if (!requeue(r)) return Error::make(Errc::Io, "libcamera: requeue failed");
                continue;
            }
            CameraControls got;
            if (exposureUs) got.exposureUs = *exposureUs;
            if (const auto g = meta.get(lc::controls::AnalogueGain)) got.analogueGain = *g;
            if (const auto cg = meta.get(lc::controls::ColourGains)) {
                got.redGain = (*cg)[0];
                got.blueGain = (*cg)[1];
            }
            if (const auto lens = meta.get(lc::controls::LensPosition)) got.lensPosition = *lens;
            got.sharpness = options_.controls.sharpness; // not reported per frame
            got.noiseReduction = options_.controls.noiseReduction;
            // After setControls(): frames of requests queued before it, and those that do not
            // show it yet, go back (the pipeline applies controls a few frames late); after
            // kSettleFrames the frame is taken as it is, its metadata saying what it used.
            if (s.changing) {
                const bool before = s.queuedIn[size_t(r->cookie())] < s.generation;
                if (before || (!showsChange(s.change, got) && --s.changeFramesLeft > 0)) {
                    ++stale;
                    if (!requeue(r)) return Error::make(Errc::Io, "libcamera: requeue failed");
                    continue;
                }
                s.changing = false;
            }
            s.held = r;
            const Mapping &map = *s.maps[size_t(r->cookie())];
            out->view = {s.format, map.luma, s.width, s.height, s.stride, map.lumaBytes};
            const int64_t startNs = exposureStartNs(stamp);
            out->timestampMs = monotonicNsOnClockMs(clock_, startNs);
            out->latencyUs = (startNs - notBeforeNs) / 1000;
            out->exposureUs = stamp.exposureNs / 1000;
            out->sequence = md.sequence;
            out->staleFrames = stale;
            out->controls = got;
            s.lensPosition = float(got.lensPosition);
            const auto af = meta.get(lc::controls::AfState);
            s.afState = af ? int(*af) : -1;
            out->source = source_;
            return {};
        }
        if (s.cv.wait_until(lock, deadline) == std::cv_status::timeout && s.done.empty() && !s.gone)
            return Error::make(Errc::Timeout, "libcamera: no frame exposed after the LED settled within " +
                                                  std::to_string(timeoutMs) + " ms (" + std::to_string(stale) +
                                                  " earlier frames refused)");
    }
}

namespace {

// v within the limits the camera lists for the control (its current mode's, on a Raspberry
// Pi: the exposure's upper limit is the frame duration's).
template <typename T> T withinLimits(const lc::Camera &cam, const lc::ControlId &id, T v)
{
    const auto it = cam.controls().find(id.id());
    if (it == cam.controls().end()) return v;
    const lc::ControlValue &lo = it->second.min(), &hi = it->second.max();
    constexpr lc::ControlType type = std::is_same_v<T, float> ? lc::ControlTypeFloat : lc::ControlTypeInteger32;
    if (lo.type() == type && !lo.isArray() && v < lo.get<T>()) v = lo.get<T>();
    if (hi.type() == type && !hi.isArray() && hi.get<T>() > lo.get<T>() && v > hi.get<T>()) v = hi.get<T>();
    return v;
}

} // namespace

Result<CameraControls> LibcameraCamera::setControls(const CameraControls &asked)
{
    if (!configured_) return Result<CameraControls>::fail(Errc::Invalid, "camera: not configured");
    if (!session_)
        if (Error e = configure(wanted_); !e.ok()) return {{}, e};
    Session &s = *session_;
    const lc::Camera &cam = *s.camera;
    std::string missing;
    auto need = [&](bool set, const lc::ControlId &id) {
        if (set && !supports(cam, id)) missing += (missing.empty() ? "" : ", ") + std::string(id.name());
    };
    const bool colour = asked.redGain >= 0 || asked.blueGain >= 0;
    need(asked.exposureUs >= 0, lc::controls::ExposureTime);
    need(asked.analogueGain >= 0, lc::controls::AnalogueGain);
    need(colour, lc::controls::ColourGains);
    need(asked.lensPosition >= 0, lc::controls::AfMode);
    need(asked.lensPosition >= 0, lc::controls::LensPosition);
    need(asked.sharpness >= 0, lc::controls::Sharpness);
    need(asked.noiseReduction >= 0, lc::controls::draft::NoiseReductionMode);
    if (!missing.empty())
        return Result<CameraControls>::fail(Errc::Invalid, "libcamera: " + modelOf(cam) + " has no " + missing +
                                                               " control (nothing changed)");
    // Colour gains go as a pair: the one not asked stays as it is.
    const double red = asked.redGain >= 0 ? asked.redGain : options_.controls.redGain;
    const double blue = asked.blueGain >= 0 ? asked.blueGain : options_.controls.blueGain;
    if (colour && (red < 0 || blue < 0))
        return Result<CameraControls>::fail(Errc::Invalid, "libcamera: colour gains are set as a pair (red and blue)");
    // On the next request queued, as rpicam-apps' SetControls and picamera2's set_controls
    // do; the pipeline carries them over to every frame after.
    CameraControls took;
    if (asked.exposureUs >= 0) {
        took.exposureUs = withinLimits(cam, lc::controls::ExposureTime, int32_t(asked.exposureUs));
        s.pending.set(lc::controls::ExposureTime, int32_t(took.exposureUs));
    }
    if (asked.analogueGain >= 0) {
        took.analogueGain = withinLimits(cam, lc::controls::AnalogueGain, float(asked.analogueGain));
        s.pending.set(lc::controls::AnalogueGain, float(took.analogueGain));
    }
    if (colour) {
        took.redGain = red;
        took.blueGain = blue;
        const std::array<float, 2> gains{float(red), float(blue)};
        s.pending.set(lc::controls::AwbEnable, false);
        s.pending.set(lc::controls::ColourGains, lc::Span<const float, 2>(gains));
    }
    if (asked.lensPosition >= 0) {
        took.lensPosition = withinLimits(cam, lc::controls::LensPosition, float(asked.lensPosition));
        s.pending.set(lc::controls::AfMode, lc::controls::AfModeManual);
        s.pending.set(lc::controls::LensPosition, float(took.lensPosition));
    }
    if (asked.sharpness >= 0) {
        took.sharpness = asked.sharpness;
        s.pending.set(lc::controls::Sharpness, float(asked.sharpness));
    }
    if (asked.noiseReduction >= 0) {
        took.noiseReduction = asked.noiseReduction;
        s.pending.set(lc::controls::draft::NoiseReductionMode, int32_t(asked.noiseReduction));
    }
    // The frames to wait for: the ones that report the values taken (capture()).
    s.change.before = options_.controls;
    s.change.asked = {};
    s.change.asked.exposureUs = took.exposureUs;
    s.change.asked.analogueGain = took.analogueGain;
    s.change.asked.lensPosition = took.lensPosition;
    s.changing = true;
    s.changeFramesLeft = kSettleFrames;
    ++s.generation;
    mergeControls(&options_.controls, took); // and after a reconfigure
    return {took, {}};
}

Result<double> LibcameraCamera::focusOnce(int timeoutMs)
{
    if (!configured_) return Result<double>::fail(Errc::Invalid, "camera: not configured");
    if (!session_)
        if (Error e = configure(wanted_); !e.ok()) return {0, e};
    {
        Session &s = *session_;
        if (!supports(*s.camera, lc::controls::AfTrigger) || !supports(*s.camera, lc::controls::LensPosition))
            return Result<double>::fail(Errc::Invalid,
                                        "libcamera: " + modelOf(*s.camera) + " has no autofocus (fixed focus)");
        // A one-shot sweep, as rpicam-still --autofocus-on-capture: auto mode, triggered.
        s.pending.set(lc::controls::AfMode, lc::controls::AfModeAuto);
        s.pending.set(lc::controls::AfTrigger, lc::controls::AfTriggerStart);
    }
    const int64_t deadline = clock_.monotonicMs() + timeoutMs;
    bool scanned = false;
    while (clock_.monotonicMs() < deadline) {
        CapturedFrame frame;
        if (Error e = capture(CaptureRequest{CaptureRequest::kAtCall, timeoutMs}, &frame); !e.ok()) return {0, e};
        if (!session_) return Result<double>::fail(Errc::Closed, "libcamera: camera disconnected");
        const Session &s = *session_;
        // Frames queued before the trigger still say Idle or Focused: the sweep's own
        // answer comes after it reported Scanning.
        if (s.afState == lc::controls::AfStateScanning) scanned = true;
        if (!scanned) continue;
        CameraControls hold;
        if (s.afState == lc::controls::AfStateFocused) {
            hold.lensPosition = s.lensPosition;
            if (const auto r = setControls(hold); !r.ok()) return {0, r.error};
            return {hold.lensPosition, {}};
        }
        if (s.afState == lc::controls::AfStateFailed) {
            hold.lensPosition = options_.controls.lensPosition >= 0 ? options_.controls.lensPosition : 0;
            (void)setControls(hold);
            return Result<double>::fail(Errc::Timeout, "libcamera: autofocus found nothing sharp");
        }
    }
    return Result<double>::fail(Errc::Timeout,
                                "libcamera: autofocus did not settle within " + std::to_string(timeoutMs) + " ms");
}

} // namespace icacam::hal
