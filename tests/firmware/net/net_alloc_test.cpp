// The device's side of the network seam allocates nothing: what a measurement's report
// calls (a listener's onLine and onJournaled) and what each loop pass calls (the inbox's
// pop) copy into memory sized before. Its own program: the allocation counter replaces
// operator new program-wide.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "firmware/net/aim_exchange.h"
#include "firmware/net/command_inbox.h"
#include "firmware/net/line_exchange.h"
#include "firmware/net/mqtt_publisher.h"
#include "hal/file/folder_storage.h"
#include "tests/support/allocation_counter.h"
#include "tests/support/temp_dir.h"

namespace icacam::fw::net {
namespace {

TEST(NetSeam, ListenersAndTheInboxAllocateNothingOnTheDevicesThread)
{
    test::TempDir dir;
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir.path).ok());
    MqttPublisher mqtt({"127.0.0.1", 1, "t", "id", 30}, storage, dir.path + "/journal.jsonl");
    LineExchange lines;
    AimExchange aim;
    CommandInbox inbox;
    std::vector<uint8_t> frame(1456 * 1088, 100); // a frame as the sample's
    const vision::LumaView picture{frame.data(), 1456, 1088, 1456, 1};
    const std::string result(1500, 'r'); // a record line is about 1.2 kB
    char out[CommandInbox::kMaxLine];
    inbox.push("status");
    lines.onLine(result); // the first use of each slot is no different from the next
    const long before = test::allocationCount();
    for (int i = 0; i < 200; ++i) {
        lines.onLine(result);
        lines.onJournaled(i);
        mqtt.onLine(result);
        mqtt.onJournaled(i);
        inbox.pop(out);
        aim.onAimPicture(picture);
    }
    EXPECT_EQ(test::allocationCount(), before);
}

} // namespace
} // namespace icacam::fw::net
