#pragma once
// Command-line options read one way by every `icacam` subcommand: `--name value` and
// `--name=value`, flags without a value, and a specific error naming the option for a
// missing or malformed value or an unknown option. main() prints that error with the
// command's usage and exits 2; --help prints the usage and exits 0.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace icacam::host::cli {

// A mistake on the command line, with the usage of the command it was made in.
class UsageError : public std::runtime_error {
public:
    UsageError(const std::string &what, std::string usage) : std::runtime_error(what), usage_(std::move(usage)) {}
    const std::string &usage() const { return usage_; }

private:
    std::string usage_;
};

// Walks the arguments of one command:
//   OptionReader r(args, kUsage);
//   while (r.next()) {
//       if (r.isHelp()) { print usage; return 0; }
//       else if (r.is("--out")) out = r.value();
//       else if (r.is("--hard")) hard = r.flag();
//       else r.unknown();
//   }
class OptionReader {
public:
    OptionReader(const std::vector<std::string> &args, std::string usage, size_t from = 0);

    bool next();                                          // to the next argument; false after the last
    const std::string &arg() const { return args_[at_]; } // as written
    const std::string &name() const { return name_; }     // an option's name, without "=value"
    bool is(std::string_view name) const { return isOption() && name_ == name; }
    bool isOption() const; // "-x" or "--x" (a lone "-" is a value)
    bool isHelp() const { return name_ == "-h" || name_ == "--help"; }

    std::string value();                 // after '=', else the next argument
    bool flag();                         // an option without a value: true
    double number();                     // value() as a finite number
    double number(double lo, double hi); // … within [lo, hi]
    long wholeNumber(long lo, long hi);  // … a whole number within [lo, hi]
    std::vector<std::string> rest();     // this argument and every one after it

    [[noreturn]] void unknown() const;                        // "unknown option '--x'" (or argument)
    [[noreturn]] void fail(const std::string &why) const;     // "--x: why"
    [[noreturn]] void missing(const std::string &what) const; // "missing: what"
    const std::string &usage() const { return usage_; }

private:
    const std::vector<std::string> &args_;
    std::string usage_;
    size_t at_;
    bool started_ = false;
    std::string name_, inlineValue_;
    bool hasInline_ = false;
};

// A whole string as a finite number ("1e5", "-0.25"); false for anything else.
bool parseFinite(const std::string &text, double *out);

// The friction models the factory knows, comma-separated (friction/friction_models.h).
std::string modelNames();

} // namespace icacam::host::cli
