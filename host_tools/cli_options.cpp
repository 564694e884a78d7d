#include "host_tools/cli_options.h"

#include <cmath>
#include <cstdlib>

#include "friction/friction_models.h"
#include "host_tools/number_text.h"

namespace icacam::host::cli {

OptionReader::OptionReader(const std::vector<std::string> &args, std::string usage, size_t from)
        : args_(args), usage_(std::move(usage)), at_(from)
{}

bool OptionReader::next()
{
    if (started_) ++at_;
    started_ = true;
    name_.clear();
    inlineValue_.clear();
    hasInline_ = false;
    if (at_ >= args_.size()) return false;
    name_ = args_[at_];
    // "--name=value": only long options carry their value after '='.
    if (name_.rfind("--", 0) == 0)
        if (const size_t eq = name_.find('='); eq != std::string::npos) {
            inlineValue_ = name_.substr(eq + 1);
            name_.resize(eq);
            hasInline_ = true;
        }
    return true;
}

bool OptionReader::isOption() const
{
    return name_.size() > 1 && name_[0] == '-';
}

std::string OptionReader::value()
{
    if (hasInline_) return inlineValue_;
    if (at_ + 1 >= args_.size()) throw UsageError(name_ + " needs a value", usage_);
    return args_[++at_];
}

bool OptionReader::flag()
{
    if (hasInline_) fail("takes no value (given '" + inlineValue_ + "')");
    return true;
}

double OptionReader::number()
{
    const std::string v = value();
    double x;
    if (!parseFinite(v, &x)) fail("not a number: '" + v + "'");
    return x;
}

double OptionReader::number(double lo, double hi)
{
    const std::string v = value();
    double x;
    if (!parseFinite(v, &x) || x < lo || x > hi)
        fail("a number from " + numberText("%g", lo) + " to " + numberText("%g", hi) + ", not '" + v + "'");
    return x;
}

long OptionReader::wholeNumber(long lo, long hi)
{
    const std::string v = value();
    double x;
    if (!parseFinite(v, &x) || x != std::floor(x) || x < double(lo) || x > double(hi))
        fail("a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", not '" + v + "'");
    return long(x);
}

std::vector<std::string> OptionReader::rest()
{
    std::vector<std::string> r(args_.begin() + long(at_), args_.end());
    at_ = args_.size();
    return r;
}

void OptionReader::unknown() const
{
    throw UsageError(std::string(isOption() ? "unknown option '" : "unexpected argument '") + name_ + "'", usage_);
}

void OptionReader::fail(const std::string &why) const
{
    throw UsageError(name_ + ": " + why, usage_);
}

void OptionReader::missing(const std::string &what) const
{
    throw UsageError("missing: " + what, usage_);
}

bool parseFinite(const std::string &text, double *out)
{
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
    char *end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(v)) return false;
    *out = v;
    return true;
}

std::string modelNames()
{
    std::string s;
    for (std::string_view n : friction::kModelNames) (s += s.empty() ? "" : ", ") += n;
    return s;
}

} // namespace icacam::host::cli
