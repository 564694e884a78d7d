#include "hal/libcamera/tuning.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "hal/unique_fd.h"

namespace icacam::hal {

namespace {

// The index just past the JSON value's end that starts at `at` (an object or array, with
// strings skipped), or npos when it is not closed.
size_t endOfContainer(std::string_view s, size_t at)
{
    int depth = 0;
    bool inString = false;
    for (size_t i = at; i < s.size(); ++i) {
        const char c = s[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"')
            inString = true;
        else if (c == '{' || c == '[')
            ++depth;
        else if (c == '}' || c == ']') {
            if (--depth == 0) return i + 1;
        }
    }
    return std::string_view::npos;
}

size_t skipSpace(std::string_view s, size_t i)
{
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
    return i;
}

// The position of `key` as a member of the object [begin, end) itself, not of one nested in it.
size_t memberAt(std::string_view s, size_t begin, size_t end, std::string_view key)
{
    bool inString = false;
    int depth = 0;
    for (size_t i = begin; i < end; ++i) {
        const char c = s[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '{' || c == '[')
            ++depth;
        else if (c == '}' || c == ']')
            --depth;
        else if (c == '"') {
            if (depth == 1 && s.compare(i, key.size(), key) == 0) return i;
            inString = true;
        }
    }
    return std::string_view::npos;
}

Error readFile(const std::string &path, std::string *out)
{
    UniqueFd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (!fd.valid()) return Error::make(Errc::Io, path + ": " + std::strerror(errno));
    out->clear();
    char buf[16384];
    for (;;) {
        const ssize_t n = ::read(fd.get(), buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return Error::make(Errc::Io, path + ": " + std::strerror(errno));
        if (n == 0) return {};
        out->append(buf, size_t(n));
    }
}

Error writeFile(const std::string &path, std::string_view text)
{
    UniqueFd fd(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    if (!fd.valid()) return Error::make(Errc::Io, path + ": " + std::strerror(errno));
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd.get(), text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return Error::make(Errc::Io, path + ": " + std::strerror(errno));
        done += size_t(n);
    }
    return {};
}

bool isFile(const std::string &path)
{
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// The "rpi.contrast" block: its opening brace and the index just past its closing one.
Error contrastBlock(std::string_view tuning, size_t *open, size_t *close)
{
    constexpr std::string_view kBlock = "\"rpi.contrast\"";
    const size_t block = tuning.find(kBlock);
    if (block == std::string_view::npos)
        return Error::make(Errc::BadFormat, "tuning file has no \"rpi.contrast\" block");
    *open = skipSpace(tuning, block + kBlock.size());
    if (*open < tuning.size() && tuning[*open] == ':') *open = skipSpace(tuning, *open + 1);
    if (*open >= tuning.size() || tuning[*open] != '{')
        return Error::make(Errc::BadFormat, "tuning file: \"rpi.contrast\" is not an object");
    *close = endOfContainer(tuning, *open);
    if (*close == std::string_view::npos)
        return Error::make(Errc::BadFormat, "tuning file: \"rpi.contrast\" is not closed");
    return {};
}

} // namespace

Error withoutAdaptiveContrast(std::string_view tuning, std::string *out)
{
    constexpr std::string_view kKey = "\"ce_enable\"";
    size_t open = 0, close = 0;
    if (Error e = contrastBlock(tuning, &open, &close); !e.ok()) return e;
    const size_t key = memberAt(tuning, open, close, kKey);
    if (key == std::string_view::npos) {
        // Absent means enabled (Contrast::read defaults it to 1): say 0 first thing.
        out->assign(tuning.substr(0, open + 1));
        out->append(" \"ce_enable\": 0,");
        out->append(tuning.substr(open + 1));
        return {};
    }
    size_t value = skipSpace(tuning, key + kKey.size());
    if (value >= close || tuning[value] != ':')
        return Error::make(Errc::BadFormat, "tuning file: \"ce_enable\" has no value");
    value = skipSpace(tuning, value + 1);
    size_t valueEnd = value;
    while (valueEnd < close && tuning[valueEnd] != ',' && tuning[valueEnd] != '}' && tuning[valueEnd] != ' ' &&
           tuning[valueEnd] != '\t' && tuning[valueEnd] != '\r' && tuning[valueEnd] != '\n')
        ++valueEnd;
    if (valueEnd == value) return Error::make(Errc::BadFormat, "tuning file: \"ce_enable\" has no value");
    out->assign(tuning.substr(0, value));
    out->append("0");
    out->append(tuning.substr(valueEnd));
    return {};
}

Error withFixedTone(std::string_view tuning, double gamma, std::string *out)
{
    if (!(gamma >= 1 && gamma <= 3)) return Error::make(Errc::Invalid, "tone curve: gamma must lie in 1-3");
    std::string noCe;
    if (Error e = withoutAdaptiveContrast(tuning, &noCe); !e.ok()) return e;
    std::string curve = "[ 0, 0";
    if (gamma == 1) {
        curve += ", 65535, 65535";
    } else {
        constexpr int kPoints = 32;
        for (int i = 1; i <= kPoints; ++i) {
            const double x = double(i * i) / (kPoints * kPoints);
            curve += ", " + std::to_string(std::lround(65535 * x)) + ", " +
                     std::to_string(std::lround(65535 * std::pow(x, 1 / gamma)));
        }
    }
    curve += " ]";
    constexpr std::string_view kKey = "\"gamma_curve\"";
    const std::string_view text = noCe;
    size_t open = 0, close = 0;
    if (Error e = contrastBlock(text, &open, &close); !e.ok()) return e;
    const size_t key = memberAt(text, open, close, kKey);
    if (key == std::string_view::npos) {
        out->assign(text.substr(0, open + 1));
        out->append(" \"gamma_curve\": " + curve + ",");
        out->append(text.substr(open + 1));
        return {};
    }
    size_t value = skipSpace(text, key + kKey.size());
    if (value < close && text[value] == ':') value = skipSpace(text, value + 1);
    const size_t valueEnd = value < close && text[value] == '[' ? endOfContainer(text, value) : std::string_view::npos;
    if (valueEnd == std::string_view::npos || valueEnd > close)
        return Error::make(Errc::BadFormat, "tuning file: \"gamma_curve\" is not a list");
    out->assign(text.substr(0, value));
    out->append(curve);
    out->append(text.substr(valueEnd));
    return {};
}

Error writeFixedToneTuning(std::span<const std::string_view> dataDirs, std::string_view model,
                           const std::string &outDir, double gamma, TuningOverride *out)
{
    *out = {};
    if (!(gamma >= 1 && gamma <= 3)) return Error::make(Errc::Invalid, "tone curve: gamma must lie in 1-3");
    if (model.empty()) return {};
    const std::string name = std::string(model) + ".json";
    std::string text, fixed;
    for (std::string_view module : kRpiIpaModules) {
        for (std::string_view dir : dataDirs) {
            const std::string from = std::string(dir) + "/" + std::string(module) + "/" + name;
            if (!isFile(from)) continue;
            if (Error e = readFile(from, &text); !e.ok()) return e;
            if (Error e = withFixedTone(text, gamma, &fixed); !e.ok())
                return Error::make(e.code, from + ": " + e.message);
            const std::string toDir = outDir + "/" + std::string(module);
            std::error_code ec;
            std::filesystem::create_directories(toDir, ec);
            if (ec) return Error::make(Errc::Io, toDir + ": " + ec.message());
            if (Error e = writeFile(toDir + "/" + name, fixed); !e.ok()) return e;
            if (out->files++ == 0) out->source = from;
            break; // libcamera takes the first directory that has it
        }
    }
    return {};
}

} // namespace icacam::hal
