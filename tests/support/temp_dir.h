#pragma once
// A fresh folder under /tmp for one test, removed with everything in it when the test ends.
#include <stdlib.h>

#include <filesystem>
#include <string>

namespace icacam::test {

struct TempDir {
    std::string path;
    explicit TempDir(const char *prefix = "icacam-test")
    {
        std::string tmpl = std::string("/tmp/") + prefix + "-XXXXXX";
        path = ::mkdtemp(tmpl.data());
    }
    ~TempDir() { std::filesystem::remove_all(path); }
    TempDir(const TempDir &) = delete;
    TempDir &operator=(const TempDir &) = delete;
};

} // namespace icacam::test
