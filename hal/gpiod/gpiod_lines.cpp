// libgpiod backends. ICACAM_GPIOD_API (from pkg-config's version, hal/gpiod/CMakeLists.txt)
// selects libgpiod 1.6's API (line objects that belong to the chip) or 2.x's (line requests built
// from settings); above the #if both present the same small set of operations.
#include "hal/gpiod/gpiod_lines.h"

#include <gpiod.h>
#include <poll.h>
#include <time.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

namespace icacam::hal {

namespace {

constexpr int kEventBatch = 16; // edges read per call; more wait for the next call

Error fromErrno(const char *what, const std::string &path, int err)
{
    const Errc c = (err == ENOENT || err == ENODEV || err == ENOTTY) ? Errc::NotFound : Errc::Io;
    return Error::make(c, std::string(what) + " " + path + ": " + std::strerror(err));
}

int64_t monotonicNs()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// Edges are stamped by the kernel on CLOCK_MONOTONIC; the HAL's Clock may have another
// origin (a test's manual clock), so the edge is placed by its age.
int64_t toClockMs(const Clock &clock, int64_t edgeNs)
{
    const int64_t ageNs = monotonicNs() - edgeNs;
    return clock.monotonicMs() - (ageNs > 0 ? ageNs / 1000000 : 0);
}

// The chips a named line is looked for on: the configured one first, then all.
template <typename Fn> bool forEachChip(const std::string &first, Fn &&fn)
{
    if (fn(first)) return true;
    for (int i = 0; i < 16; ++i) {
        const std::string p = "/dev/gpiochip" + std::to_string(i);
        if (p != first && fn(p)) return true;
    }
    return false;
}

} // namespace

void parseGpioLine(const std::string &text, GpioLineSpec *spec)
{
    bool digits = !text.empty();
    for (char c : text) digits = digits && std::isdigit(static_cast<unsigned char>(c));
    if (digits) {
        spec->offset = unsigned(std::strtoul(text.c_str(), nullptr, 10));
        spec->name.clear();
    } else {
        spec->name = text;
    }
}

#if ICACAM_GPIOD_API >= 2
// ---- libgpiod 2.x --------------------------------------------------------------------
struct LineRequest {
    gpiod_chip *chip = nullptr;
    gpiod_line_request *request = nullptr;
    gpiod_edge_event_buffer *events = nullptr;
    unsigned offset = 0;
    std::string chipPath;

    LineRequest() = default;
    LineRequest(const LineRequest &) = delete;
    LineRequest &operator=(const LineRequest &) = delete;
    ~LineRequest()
    {
        if (events) gpiod_edge_event_buffer_free(events);
        if (request) gpiod_line_request_release(request);
        if (chip) gpiod_chip_close(chip);
    }

    // Returns 0 or an errno value.
    int open(const GpioLineSpec &spec, const char *consumer, bool output)
    {
        offset = spec.offset;
        if (!spec.name.empty()) {
            const bool found = forEachChip(spec.chipPath, [&](const std::string &path) {
                gpiod_chip *c = gpiod_chip_open(path.c_str());
                if (!c) return false;
                const int off = gpiod_chip_get_line_offset_from_name(c, spec.name.c_str());
                if (off < 0) {
                    gpiod_chip_close(c);
                    return false;
                }
                chip = c;
                offset = unsigned(off);
                chipPath = path;
                return true;
            });
            if (!found) return ENOENT;
        } else {
            chip = gpiod_chip_open(spec.chipPath.c_str());
            if (!chip) return errno;
            chipPath = spec.chipPath;
        }
        gpiod_line_settings *settings = gpiod_line_settings_new();
        gpiod_line_config *lineCfg = gpiod_line_config_new();
        gpiod_request_config *reqCfg = gpiod_request_config_new();
        int err = (settings && lineCfg && reqCfg) ? 0 : ENOMEM;
        if (!err) {
            if (output) {
                gpiod_line_settings_set_direction(settings, GPIOD_LINE_DIRECTION_OUTPUT);
                gpiod_line_settings_set_output_value(settings, spec.activeLow ? GPIOD_LINE_VALUE_ACTIVE
                                                                              : GPIOD_LINE_VALUE_INACTIVE);
            } else {
                gpiod_line_settings_set_direction(settings, GPIOD_LINE_DIRECTION_INPUT);
                gpiod_line_settings_set_edge_detection(settings, GPIOD_LINE_EDGE_BOTH);
                gpiod_line_settings_set_event_clock(settings, GPIOD_LINE_CLOCK_MONOTONIC);
                if (spec.pullUp)
                    gpiod_line_settings_set_bias(settings, GPIOD_LINE_BIAS_PULL_UP);
                else if (spec.pullDown)
                    gpiod_line_settings_set_bias(settings, GPIOD_LINE_BIAS_PULL_DOWN);
                else if (spec.biasOff)
                    gpiod_line_settings_set_bias(settings, GPIOD_LINE_BIAS_DISABLED);
                // The kernel filters bounce before it stamps the edge (v2 only).
                if (spec.debounceUs > 0)
                    gpiod_line_settings_set_debounce_period_us(settings, static_cast<unsigned long>(spec.debounceUs));
            }
            gpiod_request_config_set_consumer(reqCfg, consumer);
            if (gpiod_line_config_add_line_settings(lineCfg, &offset, 1, settings) != 0) err = errno;
        }
        if (!err) {
            request = gpiod_chip_request_lines(chip, reqCfg, lineCfg);
            if (!request) err = errno;
        }
        if (!err && !output) {
            events = gpiod_edge_event_buffer_new(kEventBatch);
            if (!events) err = ENOMEM;
        }
        if (reqCfg) gpiod_request_config_free(reqCfg);
        if (lineCfg) gpiod_line_config_free(lineCfg);
        if (settings) gpiod_line_settings_free(settings);
        return err;
    }
    int fd() const { return gpiod_line_request_get_fd(request); }
    int setRaw(bool high)
    {
        return gpiod_line_request_set_value(request, offset,
                                            high ? GPIOD_LINE_VALUE_ACTIVE : GPIOD_LINE_VALUE_INACTIVE) == 0
                   ? 0
                   : errno;
    }
    // 1 high, 0 low, -errno.
    int getRaw()
    {
        const gpiod_line_value v = gpiod_line_request_get_value(request, offset);
        if (v == GPIOD_LINE_VALUE_ERROR) return -errno;
        return v == GPIOD_LINE_VALUE_ACTIVE ? 1 : 0;
    }
    // Reads up to cap edges into (rising, ns) pairs; returns the count or -errno.
    int readEdges(bool *rising, int64_t *ns, int cap)
    {
        const int n = gpiod_line_request_read_edge_events(request, events, size_t(cap));
        if (n < 0) return -errno;
        for (int i = 0; i < n; ++i) {
            gpiod_edge_event *e = gpiod_edge_event_buffer_get_event(events, unsigned(i));
            rising[i] = gpiod_edge_event_get_event_type(e) == GPIOD_EDGE_EVENT_RISING_EDGE;
            ns[i] = int64_t(gpiod_edge_event_get_timestamp_ns(e));
        }
        return n;
    }
};
#else
// ---- libgpiod 1.6 --------------------------------------------------------------------
struct LineRequest {
    gpiod_chip *chip = nullptr;
    gpiod_line *line = nullptr; // belongs to the chip
    gpiod_line_event events[kEventBatch] = {};
    unsigned offset = 0;
    std::string chipPath;

    LineRequest() = default;
    LineRequest(const LineRequest &) = delete;
    LineRequest &operator=(const LineRequest &) = delete;
    ~LineRequest()
    {
        if (chip) gpiod_chip_close(chip); // releases the line too
    }

    int open(const GpioLineSpec &spec, const char *consumer, bool output)
    {
        if (!spec.name.empty()) {
            const bool found = forEachChip(spec.chipPath, [&](const std::string &path) {
                gpiod_chip *c = gpiod_chip_open(path.c_str());
                if (!c) return false;
                gpiod_line *l = gpiod_chip_find_line(c, spec.name.c_str());
                if (!l) {
                    gpiod_chip_close(c);
                    return false;
                }
                chip = c;
                line = l;
                chipPath = path;
                return true;
            });
            if (!found) return ENOENT;
        } else {
            chip = gpiod_chip_open(spec.chipPath.c_str());
            if (!chip) return errno;
            chipPath = spec.chipPath;
            line = gpiod_chip_get_line(chip, spec.offset);
            if (!line) return errno;
        }
        offset = gpiod_line_offset(line);
        int rc;
        if (output) {
            rc = gpiod_line_request_output(line, consumer, spec.activeLow ? 1 : 0);
        } else {
            const int flags = spec.pullUp     ? GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP
                              : spec.pullDown ? GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN
                              : spec.biasOff  ? GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE
                                              : 0;
            rc = gpiod_line_request_both_edges_events_flags(line, consumer, flags);
        }
        return rc == 0 ? 0 : errno;
    }
    int fd() const { return gpiod_line_event_get_fd(line); }
    int setRaw(bool high) { return gpiod_line_set_value(line, high ? 1 : 0) == 0 ? 0 : errno; }
    int getRaw()
    {
        const int v = gpiod_line_get_value(line);
        return v < 0 ? -errno : v;
    }
    int readEdges(bool *rising, int64_t *ns, int cap)
    {
        const int n = gpiod_line_event_read_multiple(line, events, unsigned(cap));
        if (n < 0) return -errno;
        for (int i = 0; i < n; ++i) {
            rising[i] = events[i].event_type == GPIOD_LINE_EVENT_RISING_EDGE;
            ns[i] = int64_t(events[i].ts.tv_sec) * 1000000000 + events[i].ts.tv_nsec;
        }
        return n;
    }
};
#endif

// ---- the HAL classes -------------------------------------------------------------------
struct GpiodTrigger::Lines : LineRequest {};
struct GpiodLed::Line : LineRequest {
    bool activeLow = false;
    bool on = false;   // as last switched (true after a failed switch: maybe lit)
    std::string where; // "LED segment 2 line /dev/gpiochip0:22", for errors
};

GpiodTrigger::GpiodTrigger(const Clock &clock) : clock_(clock) {}
GpiodTrigger::~GpiodTrigger() = default;
void GpiodTrigger::close()
{
    lines_.reset();
}

Error GpiodTrigger::open(const GpioLineSpec &spec, const char *consumer)
{
    close();
    auto lines = std::make_unique<Lines>();
    // The request is raw (no kernel active-low): which edge is a press is decided here, the
    // same way for both API versions.
    if (const int err = lines->open(spec, consumer, false))
        return fromErrno("trigger line",
                         spec.name.empty() ? spec.chipPath + ":" + std::to_string(spec.offset)
                                           : spec.name + " (on any /dev/gpiochipN)",
                         err);
    activeLow_ = spec.activeLow;
    where_ = lines->chipPath + ":" + std::to_string(lines->offset);
    lines_ = std::move(lines);
    return {};
}

Result<bool> GpiodTrigger::pressed()
{
    if (!lines_) return Result<bool>::fail(Errc::Invalid, "trigger line not open");
    const int v = lines_->getRaw();
    if (v < 0) return Result<bool>::fail(Errc::Io, std::string("trigger level: ") + std::strerror(-v));
    return Result<bool>{(v == 1) != activeLow_, {}};
}

Result<size_t> GpiodTrigger::readEdges(ButtonEdge *out, size_t cap)
{
    if (!lines_) return Result<size_t>::fail(Errc::Invalid, "trigger line not open");
    if (cap == 0) return {};
    pollfd p{lines_->fd(), POLLIN, 0};
    const int pr = ::poll(&p, 1, 0);
    if (pr < 0) return Result<size_t>::fail(Errc::Io, std::string("trigger poll: ") + std::strerror(errno));
    if (pr == 0) return {};
    if (p.revents & (POLLERR | POLLHUP | POLLNVAL)) return Result<size_t>::fail(Errc::Closed, "trigger line went away");
    bool rising[kEventBatch];
    int64_t ns[kEventBatch];
    const int want = cap < size_t(kEventBatch) ? int(cap) : kEventBatch;
    const int n = lines_->readEdges(rising, ns, want);
    if (n < 0) return Result<size_t>::fail(Errc::Io, std::string("trigger events: ") + std::strerror(-n));
    for (int i = 0; i < n; ++i) {
        out[i].timeMs = toClockMs(clock_, ns[i]);
        out[i].pressed = activeLow_ ? !rising[i] : rising[i];
    }
    return Result<size_t>{size_t(n), {}};
}

GpiodLed::GpiodLed() = default;
GpiodLed::~GpiodLed()
{
    close();
}

void GpiodLed::close()
{
    for (auto &line : lines_)
        if (line->on) (void)drive(*line, false);
    lines_.clear();
}

Error GpiodLed::open(const GpioLineSpec &spec, const char *consumer)
{
    return open(std::vector<GpioLineSpec>{spec}, consumer);
}

Error GpiodLed::open(const std::vector<GpioLineSpec> &specs, const char *consumer)
{
    close();
    if (specs.empty()) return Error::make(Errc::Invalid, "LED ring: no line given");
    std::vector<std::unique_ptr<Line>> lines;
    for (size_t k = 0; k < specs.size(); ++k) {
        const GpioLineSpec &spec = specs[k];
        // Requested at the off level: no segment flashes while the others are opened.
        auto line = std::make_unique<Line>();
        const std::string what = specs.size() == 1 ? "LED line" : "LED segment " + std::to_string(k) + " line";
        if (const int err = line->open(spec, consumer, true))
            return fromErrno(what.c_str(),
                             spec.name.empty() ? spec.chipPath + ":" + std::to_string(spec.offset)
                                               : spec.name + " (on any /dev/gpiochipN)",
                             err);
        line->activeLow = spec.activeLow;
        line->where = what + " " + line->chipPath + ":" + std::to_string(line->offset);
        lines.push_back(std::move(line));
    }
    lines_ = std::move(lines);
    return {};
}

Error GpiodLed::drive(Line &line, bool on)
{
    if (const int err = line.setRaw(on != line.activeLow)) {
        line.on = true; // its level is unknown: the next change switches it off again
        return Error::make(Errc::Io, line.where + ": " + std::strerror(err));
    }
    line.on = on;
    return {};
}

bool GpiodLed::isOn() const
{
    for (const auto &line : lines_)
        if (line->on) return true;
    return false;
}

Error GpiodLed::set(bool on)
{
    if (lines_.empty()) return Error::make(Errc::Invalid, "LED line not open");
    Error first;
    for (auto &line : lines_) {
        Error e = drive(*line, on);
        if (!e.ok() && first.ok()) first = std::move(e);
    }
    return first;
}

Error GpiodLed::lightSegment(int k)
{
    if (lines_.empty()) return Error::make(Errc::Invalid, "LED line not open");
    if (lines_.size() == 1) return Error::make(Errc::Invalid, "the LED ring is one line: no segment to light alone");
    if (k < 0 || k >= int(lines_.size()))
        return Error::make(Errc::Invalid, "LED segment " + std::to_string(k) + ": the ring has " +
                                              std::to_string(lines_.size()) + " (0 to " +
                                              std::to_string(lines_.size() - 1) + ")");
    Error first;
    for (size_t j = 0; j < lines_.size(); ++j)
        if (int(j) != k && lines_[j]->on)
            if (Error e = drive(*lines_[j], false); !e.ok() && first.ok()) first = std::move(e);
    if (!first.ok()) {
        // A line that may still be lit: k stays dark beside it, so two are never lit.
        if (lines_[size_t(k)]->on) (void)drive(*lines_[size_t(k)], false);
        return first;
    }
    return drive(*lines_[size_t(k)], true);
}

} // namespace icacam::hal
