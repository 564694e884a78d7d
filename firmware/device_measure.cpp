// One measurement: capture, read, journal (image, then record; fsynced), report and show.
#include "firmware/device.h"

#include <cstdio>

#include "firmware/capture_fields.h"
#include "firmware/iso_time.h"
#include "firmware/screen.h"
#include "reading/reading_record.h"

namespace icacam::fw {

void Device::measure(const char *origin, const std::string &tag)
{
    const int64_t t0 = hal_.clock.monotonicMs();
    const long id = lastId_ + 1;
    drawBusy(&screen_, id);
    showOrLog(screen_);
    reading::Reading m;
    std::string problem;
    hal::CapturedFrame frame;
    vision::LumaView luma;
    const bool captured = captureFrame(&frame, &luma, &problem, true);
    if (captured && problem.empty()) {
        if (std::string issue = instrument_.frameSizeIssue(luma.width, luma.height); !issue.empty())
            problem = "calibration '" + cal_.name + "': " + issue;
        else if (litInTurn_.count > 0 &&
                 (litInTurn_.segment[0].width != luma.width || litInTurn_.segment[0].height != luma.height)) {
            segmentProblem_ = "the segment frames are another size than the whole ring's";
            litInTurn_.count = 0;
        }
        if (problem.empty()) m = instrument_.read(luma, specimenSpec(cfg_), litInTurn_.count ? &litInTurn_ : nullptr);
        if (m.geometry.imageFlags & vision::kImageSegmentsMisplaced) segmentProblem_ = misplacedSegments(m.geometry);
    }

    state_ = State::Report;
    lastId_ = id;
    std::string storageProblem;
    const std::string imageName = captured && problem.empty() ? journalFrame(id, luma, &storageProblem) : "";
    const std::string segmentNames = imageName.empty() ? "" : journalSegments(id, &storageProblem);
    buildRecord(id, origin, tag, m, problem, captured ? &frame : nullptr, imageName, segmentNames,
                long(hal_.clock.monotonicMs() - t0));
    // The record is durable before anyone hears of it: what was reported survives a crash.
    if (hal::Error e = journal_.append(out_); !e.ok())
        storageProblem = e.code == hal::Errc::Full ? "storage full: result not journaled" : "journal: " + e.message;
    else
        journaled(id);
    send(out_);
    if (!problem.empty()) sendError("measurement_failed", problem, tag);
    // Measured without the tilt the ring was configured to give: a part that needs service.
    if (!segmentProblem_.empty()) sendError("segments", "measured without segment frames: " + segmentProblem_, tag);
    if (!storageProblem.empty()) sendError("storage", storageProblem, tag);

    char title[32];
    std::snprintf(title, sizeof title, "#%ld error", id);
    if (!problem.empty())
        drawProblem(&screen_, title, problem);
    else
        drawResult(&screen_, id, m,
                   !storageProblem.empty()    ? "STORAGE FULL"
                   : !segmentProblem_.empty() ? "SEGMENTS FAILED"
                                              : "");
    showOrLog(screen_);
    state_ = State::Idle;
}

reading::SpecimenSpec specimenSpec(const Config &c)
{
    // The config's keys under their manifest names (Config's aliases), each value printed
    // exactly (17 digits round-trip a double); the config checked their ranges already.
    const std::pair<const char *, double> values[] = {
        {"n", c.n},
        {"mm_per_px", c.mmPerPx},
        {"k_mpa", c.kMpa},
        {"d0_mm", c.d0Mm},
        {"h0_mm", c.h0Mm},
        {"h_final_mm", c.hFinalMm},
        {"working_distance_mm", c.workingDistanceMm},
        {"tone_gamma", c.toneGamma},
        {"mm_per_px_tol", c.mmPerPxTolRel},
        {"h_final_tol_mm", c.hFinalTolMm},
        {"n_tol", c.nTol},
        {"tolerance_mu", c.toleranceMu},
        {"tolerance_rel", c.toleranceRel},
    };
    char text[40];
    auto lookup = [&values, &text](std::string_view key) -> const char * {
        for (const auto &[name, value] : values)
            if (key == name) {
                std::snprintf(text, sizeof text, "%.17g", value);
                return text;
            }
        return nullptr;
    };
    reading::SpecimenSpec s;
    std::string why;
    reading::specimenFromFields(lookup, false, &s, &why);
    return s;
}

void Device::buildRecord(long id, const char *origin, const std::string &tag, const reading::Reading &m,
                         std::string_view problem, const hal::CapturedFrame *frame, std::string_view image,
                         std::string_view segmentImages, long ms)
{
    out_.clear();
    reading::JsonBuilder j(&out_);
    char when[96];
    isoTime(hal_.clock.wallMs(), when);
    j.str("type", "result").integer("id", id);
    reading::JsonRecordSink sink(&j);
    // A frame never measured (capture, LED or calibration problem) is a record without a reading.
    reading::writeReading(problem.empty() ? &m : nullptr, problem, instrument_.model().name(), sink);
    j.str("time", when);
    j.str("image", image).str("source", frame ? std::string_view(frame->source) : std::string_view());
    j.num("n", cfg_.n)
        .num("k_mpa", cfg_.kMpa)
        .num("d0_mm", cfg_.d0Mm)
        .num("h0_mm", cfg_.h0Mm)
        .num("mm_per_px", cfg_.mmPerPx, 8);
    j.num("h_final_mm", cfg_.hFinalMm);
    // Which calibration mapped the boundaries, and the plane it mapped them into.
    j.str("calibration", cal_.present ? cal_.name : "");
    if (cal_.present && m.hasValue()) j.num("plane_height_mm", cfg_.h0Mm * (1 - m.reduction), 4);
    appendRecipe(j); // the version in effect: what the fields above and the camera's were set by
    j.str("material", cfg_.material).str("trigger", origin).integer("ms", ms);
    if (frame) {
        appendCaptureFields(j, *frame, triggerMs_);
        // The lit-frame check's verdict on the last frame tried, and how many were refused.
        j.str("lit", litVerdictName(lastLit_.verdict)).integer("unlit_frames", unlitFrames_);
        // The ring lit in turn: the segment frames the reading used (0: the whole ring's
        // frame alone), saved and named as a manifest's segment_images and segment0_deg name
        // them, so `icacam loop --journal` reads the record as the device did; why none,
        // where some were asked for.
        if (cfg_.ledSegments >= vision::kMinTiltSegments) {
            j.integer("segment_frames", litInTurn_.count);
            if (litInTurn_.count > 0) j.str("segment_images", segmentImages).num("segment0_deg", cfg_.ledSegment0Deg);
            if (!segmentProblem_.empty()) j.str("segment_problem", segmentProblem_);
        }
    }
    if (!tag.empty()) j.str("tag", tag);
    j.end();
}

std::string Device::journalFrame(long id, const vision::LumaView &v, std::string *problem)
{
    if (cfg_.journalImages != "pgm") return {};
    char name[32];
    std::snprintf(name, sizeof name, "img-%06ld.pgm", id);
    const hal::Error e = saveImage(name, v);
    if (e.ok()) return name;
    *problem = e.code == hal::Errc::Full ? "storage full: image not saved" : "image not saved: " + e.message;
    return {};
}

std::string Device::journalSegments(long id, std::string *problem)
{
    std::string names;
    for (int k = 0; k < litInTurn_.count; ++k) {
        char name[40];
        std::snprintf(name, sizeof name, "img-%06ld-s%d.pgm", id, k);
        if (const hal::Error e = saveImage(name, litInTurn_.segment[k]); !e.ok()) {
            if (problem->empty())
                *problem = e.code == hal::Errc::Full ? "storage full: segment frames not saved"
                                                     : "segment frames not saved: " + e.message;
            return {};
        }
        (names += names.empty() ? "" : ";") += name;
    }
    return names;
}

hal::Error Device::saveImage(std::string_view name, const vision::LumaView &v)
{
    char header[48];
    const int n = std::snprintf(header, sizeof header, "P5\n%d %d\n255\n", v.width, v.height);
    image_.assign(header, size_t(n));
    for (int y = 0; y < v.height; ++y) {
        const uint8_t *row = v.data + size_t(y) * size_t(v.stride);
        if (v.pixelStep == 1)
            image_.append(reinterpret_cast<const char *>(row), size_t(v.width));
        else
            for (int x = 0; x < v.width; ++x) image_.push_back(char(row[size_t(x) * size_t(v.pixelStep)]));
    }
    return journal_.saveImage(name, image_);
}

} // namespace icacam::fw
