#include "firmware/parts.h"

namespace icacam::fw {

const char *Part::stateName(State s)
{
    switch (s) {
    case State::Ok: return "ok";
    case State::Missing: return "missing";
    case State::Failing: return "failing";
    }
    return "unknown";
}

hal::Error Part::open()
{
    hal::Error e = openBackend();
    const State was = state_;
    const std::string before = problem_;
    state_ = e.ok() ? State::Ok : State::Missing;
    problem_ = e.ok() ? std::string() : e.message;
    code_ = e.code;
    changed_ |= state_ != was || problem_ != before;
    return e;
}

void Part::note(const hal::Error &e)
{
    if (state_ == State::Missing) return;
    const State now = e.ok() ? State::Ok : State::Failing;
    // A full output queue (nobody reading the serial line) is the far end's business, not
    // the part's.
    if (!e.ok() && e.code == hal::Errc::Full) return;
    if (now != state_ || (!e.ok() && e.message != problem_)) changed_ = true;
    state_ = now;
    problem_ = e.ok() ? std::string() : e.message;
    code_ = e.code;
}

bool Part::takeChange()
{
    const bool c = changed_;
    changed_ = false;
    return c;
}

hal::Error DisplayPart::show(const hal::MonoBitmap &picture)
{
    if (!backend_) return hal::Error::make(hal::Errc::NotFound, "display missing: " + problem());
    hal::Error e = backend_->show(picture);
    note(e);
    return e;
}

hal::Result<size_t> SerialPart::read(char *buf, size_t cap)
{
    if (!backend_) return {0, {}};
    hal::Result<size_t> r = backend_->read(buf, cap);
    note(r.error);
    return r;
}

hal::Error SerialPart::write(std::string_view data)
{
    if (!backend_) return hal::Error::make(hal::Errc::Closed, "serial missing: " + problem());
    hal::Error e = backend_->write(data);
    note(e);
    return e;
}

hal::Result<size_t> TriggerPart::readEdges(hal::ButtonEdge *out, size_t cap)
{
    if (!backend_) return {0, {}};
    hal::Result<size_t> r = backend_->readEdges(out, cap);
    note(r.error);
    return r;
}

hal::Result<bool> TriggerPart::pressed()
{
    if (!backend_) return hal::Result<bool>::fail(hal::Errc::NotFound, "trigger missing: " + problem());
    return backend_->pressed();
}

hal::Error LedPart::set(bool on)
{
    if (!backend_) return hal::Error::make(hal::Errc::NotFound, "LED ring missing: " + problem());
    hal::Error e = backend_->set(on);
    note(e);
    return e;
}

hal::Error LedPart::lightSegment(int k)
{
    if (!backend_) return hal::Error::make(hal::Errc::NotFound, "LED ring missing: " + problem());
    hal::Error e = backend_->lightSegment(k);
    // An Invalid segment is the config's mistake, not the part failing.
    if (e.code != hal::Errc::Invalid) note(e);
    return e;
}

Parts::Parts(DisplayPart &display, SerialPart &serial, TriggerPart &trigger, LedPart &led, hal::Clock &clock,
             int retryMs)
        : parts_{&display, &serial, &trigger, &led}, clock_(clock), retryMs_(retryMs)
{}

void Parts::openAll()
{
    for (Part *p : parts_) p->open();
    nextTryMs_ = clock_.monotonicMs() + retryMs_;
}

void Parts::poll()
{
    const int64_t now = clock_.monotonicMs();
    if (now < nextTryMs_) return;
    nextTryMs_ = now + retryMs_;
    for (Part *p : parts_)
        if (p->state() == Part::State::Missing) p->open();
}

std::string Parts::missingNames() const
{
    std::string names;
    for (const Part *p : parts_)
        if (!p->ok()) (names += names.empty() ? "" : " ") += p->name();
    return names;
}

} // namespace icacam::fw
