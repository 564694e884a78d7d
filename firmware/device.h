#pragma once
// The device program's logic, on the HAL seams and the vision library:
//   idle → trigger (button or serial) → LED on → capture → LED off → measure
//        → journal (image, then record; fsynced) → send on serial → show → idle.
// Every failure on the way becomes a result with status "error", words on the display and
// an error line on serial; nothing here blocks longer than the capture timeout.
#include <memory>
#include <string>
#include <string_view>

#include "firmware/camera_health.h"
#include "firmware/command.h"
#include "firmware/config.h"
#include "firmware/debouncer.h"
#include "firmware/device_calibration.h"
#include "firmware/journal.h"
#include "firmware/lit_frame.h"
#include "firmware/net/command_inbox.h"
#include "firmware/net/device_listener.h"
#include "firmware/parts.h"
#include "firmware/recipe_book.h"
#include "firmware/recipe_camera.h"
#include "firmware/recipe_desk.h"
#include "hal/camera.h"
#include "hal/clock.h"
#include "hal/display.h"
#include "hal/led_ring.h"
#include "hal/serial_port.h"
#include "hal/storage.h"
#include "hal/trigger_button.h"
#include "reading/instrument.h"

namespace icacam::fw {

// What the config declares about the specimen and the tolerances, as the instrument takes it
// (through reading::specimenFromFields, as a manifest row's columns are).
reading::SpecimenSpec specimenSpec(const Config &c);

struct DeviceHal {
    hal::Camera &camera;
    hal::TriggerButton &trigger;
    hal::LedRing &led;
    hal::Display &display;
    hal::SerialPort &serial;
    hal::Storage &storage;
    hal::Clock &clock;
    // The display, serial, trigger and LED as stand-ins that may be missing (firmware/parts.h):
    // their changes are reported and retried. nullptr: the parts are the backends themselves.
    Parts *parts = nullptr;
    // The camera seen as the recipe sets it (firmware/recipe_camera.h): the same camera as
    // above, made again when a recipe changes what it takes only when it starts (white
    // balance temperature). nullptr: those are fixed, the rest set on the running camera.
    RecipeCamera *recipeCamera = nullptr;
};

class Device {
public:
    static constexpr size_t kMaxLine = 1024; // longer serial lines are answered with an error

    enum class State { Idle, LedOn, Capture, LedOff, Measure, Report };
    static const char *stateName(State s);

    Device(DeviceHal hal, Config cfg, const friction::FrictionModel &model);
    // Sizes all buffers, recovers the journal, loads saved settings, greets on serial.
    hal::Error start();
    // One pass of the main loop: button edges, serial input, measurements they ask for.
    void tick();

    const Config &config() const { return cfg_; }
    long lastId() const { return lastId_; }
    State state() const { return state_; }
    const CameraHealth &camera() const { return cameraHealth_; }

    // The network side (firmware/net/): listeners hear every line the device says and every
    // record journaled; an inbox's lines are handled as serial lines are. Set before start().
    static constexpr int kMaxListeners = 4;
    bool addListener(net::DeviceListener *l);
    void setInbox(net::CommandInbox *inbox) { inbox_ = inbox; }
    // Recipe saves and aim's live controls from the web (device_recipe.cpp). Before start().
    void setRecipeDesk(RecipeDesk *desk) { desk_ = desk; }
    const RecipeVersion &recipe() const { return recipes_.active(); }

private:
    void pollButton();
    void pollSerial();
    void pollInbox();
    // Recipes (device_recipe.cpp). trial (a whole config) as the next version of id: the
    // camera set as it says, the audit entry written, then in effect; "" or why not (nothing
    // changed, the camera refused, the trail could not be written).
    std::string applyRecipe(const Config &trial, std::string_view id, std::string_view who, std::string_view why);
    void pollRecipeDesk();
    void saveRecipe(const RecipeDesk::Request &r);
    void liveControls(const RecipeDesk::Request &r);
    // Aim's live controls back to the recipe's.
    void endLiveControls();
    // The camera from the controls of `from` to those of `to` (RecipeCamera::follow, or the
    // changed ones set on a camera that is not one): "" or why not, the camera as it was.
    std::string moveCamera(const Config &from, const Config &to);
    void publishRecipe();
    void appendRecipe(reading::JsonBuilder &j) const;
    std::string wallTime() const; // UTC, ISO 8601
    void journaled(long id);
    void handleLine(std::string_view line);
    // device_status.cpp: the greeting at start; `status`'s fields into j.
    void sayHello(const JournalRecovery &rec);
    void appendStatus(reading::JsonBuilder &j);
    // device_settings.cpp: settings.conf over the config at start; "" or what was wrong.
    std::string restoreSettings();
    void handleCommand(const Command &c);
    // `set KEY VALUE`: tried on a copy of the config, kept and saved when valid, the new
    // value into j; false when refused (the error already sent).
    bool applySetting(const Command &c, reading::JsonBuilder &j);
    // `results [N]`: the header line (started in j), then the last N journal lines.
    void sendResults(const Command &c, reading::JsonBuilder &j);
    void measure(const char *origin, const std::string &tag);
    void scaleCheck(const Command &c);
    // device_capture.cpp. A frame with the ring off (the lit check's reference), LED on,
    // frames until one is lit top to bottom (at most led.lit_attempts), LED off: the frame as
    // luma, or the problem in words. True when a frame was captured (problem may still say
    // why it is not measured: not lit, not convertible).
    // withSegments: a segmented ring's frames first (a measurement; a snapshot or a scale
    // check needs the whole ring's frame only).
    bool captureFrame(hal::CapturedFrame *frame, vision::LumaView *luma, std::string *problem,
                      bool withSegments = false);
    bool takeDarkReference(hal::CapturedFrame *frame, std::string *problem);
    // device_segments.cpp. A segmented ring (led.segments 3-8): a frame per segment lit
    // alone at one fixed exposure, each proven lit and copied into litInTurn_; false with the
    // reason (litInTurn_ empty: the whole ring's frame is measured alone).
    bool captureSegments(hal::CapturedFrame *frame, std::string *why);
    bool litSegments(hal::CapturedFrame *frame, int exposureUs, std::string *why);
    void sizeSegmentFrames(); // at start: led.segments frames of the largest size
    // The reading found the segments lighting from elsewhere than led.segment0_deg and the
    // lines' order say (vision/segment_bearing.h): what to set, in words.
    std::string misplacedSegments(const vision::EndFaceGeometry &g) const;
    // The segment frames saved beside the record's image (img-NNNNNN-sK.pgm), ';'-separated
    // as a manifest's segment_images, or "".
    std::string journalSegments(long id, std::string *problem);
    // One capture after litMs as luma; false with the problem in words.
    bool captureLuma(int64_t notBeforeMs, hal::CapturedFrame *frame, vision::LumaView *luma, std::string *problem);
    LitFrameOptions litOptions(int width, int height) const;
    // Loads trial's calibration.file into cal_ ("none" clears it); "" or why not.
    std::string setCalibrationFile(Config *trial);
    // Hands the loaded calibration (or none) to the instrument.
    void useCalibration(const DeviceCalibration &cal);
    void sendError(const char *code, std::string_view message, std::string_view tag);
    void send(std::string_view line);
    void showIdle(std::string_view note);
    // Aim mode (device_aim.cpp): the LED ring on and the live picture on the display with
    // the found end face, a focus score and a hint, a line on serial per picture; ended
    // by `aim off`, a press, a measurement or its time running out.
    void startAim(int seconds, const std::string &tag);
    void stopAim(const char *why);
    void aimTick();
    // `snapshot`: a frame (lit as for a measurement) with the boundaries drawn, as a PNG in
    // the journal folder; answers its name.
    void snapshot(const Command &c);
    // `fetch NAME`: a snapshot's bytes over serial, base64 in lines (device_aim.cpp).
    void fetch(const Command &c);
    // Lens and focus (device_lens.cpp): `lens POSITION` holds the lens there; `focus` lights
    // the ring, runs one autofocus sweep and holds the lens where it ended; both saved as
    // lens_position and held again after a restart (the camera keeps it across reconfigures).
    void setLens(const Command &c);
    void focus(const Command &c);
    // `measure-latency` (device_latency.cpp): the ring stepped on under a running camera, the
    // first frame lit top to bottom found, and from its stamp the most the camera's timestamps
    // lag an exposure; saved as stamp_delay_us and used from then on.
    void measureLatency(const Command &c);
    // One step: the ring off, a reference, the ring on; the stamp delay bound this step gives
    // (µs), or -1 with the problem.
    int64_t latencyStep(std::string *problem);
    void applyStampDelay();
    void sendLens(const char *by, const std::string &tag);
    // Measures the frame in luma for aim and snapshot (the same specimen and scale as a
    // measurement).
    reading::Reading measureForSetup(const vision::LumaView &luma);
    // The camera's state for `hello`, `status` and the camera line sent when it comes back.
    void appendCameraStatus(reading::JsonBuilder &j) const;
    void pollCamera();
    // Parts (device_parts.cpp): retried from the loop; each change said on serial, on the
    // display, in the journal and in the log; the missing ones in `hello` and `status`.
    void pollParts();
    void reportPart(const Part &p);
    void appendPartsStatus(reading::JsonBuilder &j) const;
    // The idle screen's last line: the missing parts when there are any, else note.
    std::string idleNote(std::string_view note) const;
    void buildRecord(long id, const char *origin, const std::string &tag, const reading::Reading &m,
                     std::string_view problem, const hal::CapturedFrame *frame, std::string_view image,
                     std::string_view segmentImages, long ms);
    // The frame saved beside its record as img-NNNNNN.pgm when the journal keeps images: its
    // name, or "" (with *problem saying why where saving failed).
    std::string journalFrame(long id, const vision::LumaView &v, std::string *problem);
    hal::Error saveImage(std::string_view name, const vision::LumaView &v);
    void persistSettings();
    void showOrLog(const hal::MonoBitmap &bmp);

    DeviceHal hal_;
    Config cfg_;
    reading::Instrument instrument_;
    CameraHealth cameraHealth_;
    int64_t triggerMs_ = 0;   // when the frame being measured was asked for
    int64_t aimUntilMs_ = -1; // aim mode runs until then (-1: off)
    int64_t aimNextMs_ = 0, aimLitMs_ = 0;
    long aimFrames_ = 0;
    std::string aimTag_;
    Journal journal_;
    Debouncer debouncer_;
    LineAssembler lines_;
    State state_ = State::Idle;
    long lastId_ = 0;
    int64_t startMs_ = 0;
    std::unique_ptr<uint8_t[]> lumaScratch_;
    size_t lumaScratchBytes_ = 0;
    std::string out_, image_;
    hal::MonoBitmap screen_;
    std::string lastProblem_;
    DeviceCalibration cal_;               // calibration.file, read at start and on `set`
    std::unique_ptr<uint8_t[]> discWork_; // the scale check's disc finder
    LitFrameCheck litCheck_;
    LitCheckResult lastLit_; // the check's verdict on the last frame captured lit
    int unlitFrames_ = 0;    // frames the check refused in the last capture
    int64_t ledOffMs_ = 0;   // when the ring was last switched off
    // The segment frames of the measurement under way (count 0: none), their pixels, and
    // why they were not taken.
    vision::LitInTurn litInTurn_;
    std::unique_ptr<uint8_t[]> segmentPixels_;
    size_t segmentFrameBytes_ = 0;
    std::string segmentProblem_;
    net::DeviceListener *listeners_[kMaxListeners] = {};
    int listenerCount_ = 0;
    net::CommandInbox *inbox_ = nullptr;
    std::unique_ptr<char[]> inboxLine_;
    const char *lineOrigin_ = "serial"; // a record's "trigger": where the command line came from
    RecipeBook recipes_;
    RecipeDesk *desk_ = nullptr;
    RecipeDesk::Request deskRequest_;
    Config live_; // aim mode's live controls over cfg_ (liveOn_)
    bool liveOn_ = false;
};

} // namespace icacam::fw
