#include "hal/file/scripted_light.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <iterator>
#include <limits>

namespace icacam::hal {

namespace {

constexpr double kForever = std::numeric_limits<double>::infinity();

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

} // namespace

Error ScriptedLight::open(const std::string &path)
{
    if (path.empty()) return {};
    std::ifstream in(path);
    if (!in) return Error::make(Errc::NotFound, "LED script '" + path + "' cannot be read");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return feed(text);
}

Error ScriptedLight::feed(std::string_view script)
{
    int lineNo = 0;
    while (!script.empty()) {
        ++lineNo;
        const size_t nl = script.find('\n');
        std::string_view line = script.substr(0, nl);
        script.remove_prefix(nl == std::string_view::npos ? script.size() : nl + 1);
        if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        line = trim(line);
        if (line.empty()) continue;
        const size_t sp = line.find(' ');
        const std::string_view word = line.substr(0, sp);
        const std::string_view arg = sp == std::string_view::npos ? std::string_view() : trim(line.substr(sp + 1));
        Step s;
        if (word == "ok" || word == "dead") {
            s.fault = word == "ok" ? Fault::Ok : Fault::Dead;
            if (!arg.empty())
                return Error::make(Errc::Invalid, "LED script line " + std::to_string(lineNo) + ": '" +
                                                      std::string(word) + "' takes no argument");
        } else if (word == "late" || word == "flash") {
            s.fault = word == "late" ? Fault::Late : Fault::Flash;
            const auto r = std::from_chars(arg.data(), arg.data() + arg.size(), s.ms);
            if (r.ec != std::errc() || r.ptr != arg.data() + arg.size() || s.ms < 0)
                return Error::make(Errc::Invalid, "LED script line " + std::to_string(lineNo) + ": '" +
                                                      std::string(word) + "' needs milliseconds");
        } else {
            return Error::make(Errc::Invalid, "LED script line " + std::to_string(lineNo) + ": unknown '" +
                                                  std::string(word) + "' (ok, late MS, dead, flash MS)");
        }
        if (stepCount_ >= kSteps)
            return Error::make(Errc::Invalid, "LED script: more than " + std::to_string(kSteps) + " lines");
        steps_[stepCount_++] = s;
    }
    return {};
}

Error ScriptedLight::setSegments(int n)
{
    if (n < 1) return Error::make(Errc::Invalid, "LED ring of " + std::to_string(n) + " segments: 1 or more");
    segments_ = n;
    return {};
}

void ScriptedLight::switched(bool on)
{
    switchTo(on ? kWholeRing : kDark);
}

void ScriptedLight::switchedSegment(int k)
{
    if (k >= 0) switchTo(k);
}

void ScriptedLight::switchTo(int what)
{
    if (what == switchedTo_) return;
    switchedTo_ = what;
    const double now = double(clock_.monotonicMs());
    // Whatever light was still to come or still on ends now.
    while (litCount_ > 0 && lit_[litCount_ - 1].onMs >= now) --litCount_;
    if (litCount_ > 0) lit_[litCount_ - 1].offMs = std::min(lit_[litCount_ - 1].offMs, now);
    if (what == kDark) return;
    const Step s = nextStep_ < stepCount_ ? steps_[nextStep_++] : Step{};
    Interval i{now, kForever, what};
    switch (s.fault) {
    case Fault::Ok: break;
    case Fault::Late: i.onMs = now + s.ms; break;
    case Fault::Dead: return;
    case Fault::Flash: i.offMs = now + s.ms; break;
    }
    if (litCount_ == kIntervals) {
        std::copy(lit_ + 1, lit_ + kIntervals, lit_);
        --litCount_;
    }
    lit_[litCount_++] = i;
}

double ScriptedLight::litFraction(double fromMs, double toMs) const
{
    return fraction(fromMs, toMs, kWholeRing);
}

double ScriptedLight::litFraction(double fromMs, double toMs, int segment) const
{
    return segment < 0 ? 0.0 : fraction(fromMs, toMs, segment);
}

double ScriptedLight::fraction(double fromMs, double toMs, int by) const
{
    if (toMs <= fromMs) {
        for (int k = 0; k < litCount_; ++k)
            if (lit_[k].by == by && fromMs >= lit_[k].onMs && fromMs < lit_[k].offMs) return 1.0;
        return 0.0;
    }
    double lit = 0;
    for (int k = 0; k < litCount_; ++k)
        if (lit_[k].by == by) lit += std::max(0.0, std::min(toMs, lit_[k].offMs) - std::max(fromMs, lit_[k].onMs));
    return std::min(1.0, lit / (toMs - fromMs));
}

} // namespace icacam::hal
