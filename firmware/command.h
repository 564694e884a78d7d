#pragma once
// The serial command language: one JSON object a line, {"cmd":"status"}, or the same as
// words for people at a terminal (`status`, `set n 0.25`, `results 5`). Parsing never fails
// loudly: anything it does not understand becomes an error the device answers with.
#include <cstddef>
#include <string>
#include <string_view>

#include "reading/record_line.h"

namespace icacam::fw {

enum class CommandKind { Help, Status, Trigger, Get, Set, Results, ScaleCheck, Aim, Snapshot };

struct Command {
    CommandKind kind = CommandKind::Help;
    std::string key;   // get / set
    std::string value; // set (numbers keep their literal text)
    int count = 10;    // results
    // scalecheck: the reference disc's declared diameter, the tolerance (percent) and the
    // disc's thickness (its edge is measured in its top face)
    double diameterMm = 0, tolerancePct = 0.5, thicknessMm = 0;
    int aimSeconds = 60; // aim: how long the live view runs (0: `aim off`)
    std::string tag;     // the request's "id", echoed in the answer
};

struct CommandParse {
    bool ok = false;
    Command cmd;
    const char *code = ""; // malformed | unknown_command | bad_argument
    std::string message;
};

constexpr int kMaxResultsAsked = 1000;
constexpr int kMaxAimSeconds = 600;
CommandParse parseCommand(std::string_view line);

// Splits a byte stream into lines of at most maxLine bytes. A longer line is reported once
// as an overflow and its bytes are dropped up to the next newline. Memory: maxLine, once.
class LineAssembler {
public:
    enum class Event { None, Line, Overflow };
    explicit LineAssembler(size_t maxLine) : max_(maxLine) { buf_.reserve(maxLine); }
    // Consumes bytes from *data until an event; returns None when *data is used up.
    Event push(std::string_view *data);
    std::string_view line() const { return buf_; }

private:
    size_t max_;
    std::string buf_;
    bool ready_ = false;
    bool discarding_ = false;
};

} // namespace icacam::fw
