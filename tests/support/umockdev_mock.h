#pragma once
// What the umockdev tests of the hardware backends share: the ioctl argument a handler
// intercepts, the mocked GPIO chip node, and the check that the preload library is loaded
// (without it the programs exit 77, skipped, like the other tests that need a device).
#include <gtest/gtest.h>
#include <umockdev.h>
#include <unistd.h>

#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string>

namespace icacam::test {

// The argument of an ioctl a umockdev handler intercepts, resolved in the client's memory as
// a T; nullptr when the pointer is bad or the data shorter than T (the handler answers EFAULT).
template <typename T> T *ioctlArg(UMockdevIoctlClient *client)
{
    UMockdevIoctlData *arg = umockdev_ioctl_client_get_arg(client);
    UMockdevIoctlData *d = arg ? umockdev_ioctl_data_resolve(arg, 0, sizeof(T), nullptr) : nullptr;
    return d && size_t(d->data_len) >= sizeof(T) ? reinterpret_cast<T *>(d->data) : nullptr;
}

// /dev/gpiochip0 in the testbed, and the /sys/bus/gpio/devices link libgpiod checks the node's
// numbers against. False with the reason in *error.
inline bool addGpioChip0(UMockdevTestbed *bed, std::string *error)
{
    GError *err = nullptr;
    const char *dev = "P: /devices/platform/gpio-mock/gpiochip0\n"
                      "N: gpiochip0\n"
                      "E: SUBSYSTEM=gpio\n"
                      "E: DEVNAME=/dev/gpiochip0\n"
                      "A: dev=254:0\\n\n";
    if (!umockdev_testbed_add_from_string(bed, dev, &err)) {
        *error = err ? err->message : "umockdev_testbed_add_from_string failed";
        if (err) g_error_free(err);
        return false;
    }
    gchar *sys = umockdev_testbed_get_sys_dir(bed);
    const std::string bus = std::string(sys) + "/bus/gpio/devices";
    g_mkdir_with_parents(bus.c_str(), 0755);
    (void)symlink((std::string(sys) + "/devices/platform/gpio-mock/gpiochip0").c_str(), (bus + "/gpiochip0").c_str());
    g_free(sys);
    return true;
}

// umockdev_in_mock_environment() answers false even under umockdev-wrapper (0.17 on
// bookworm): look for the preload library among this process's mappings instead.
inline bool umockdevPreloaded()
{
    std::FILE *f = std::fopen("/proc/self/maps", "r");
    if (!f) return false;
    char line[512];
    bool found = false;
    while (!found && std::fgets(line, sizeof line, f)) found = std::strstr(line, "libumockdev-preload") != nullptr;
    std::fclose(f);
    return found;
}

// The main() of a umockdev test program: 77 (skipped, with the reason) outside umockdev.
inline int runUnderUmockdev(int argc, char **argv, const char *program)
{
    if (!umockdevPreloaded()) {
        std::fprintf(stderr, "%s: not under umockdev (LD_PRELOAD=libumockdev-preload.so.0): skipped\n", program);
        return 77;
    }
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

} // namespace icacam::test
