#include "hal/file/folder_storage.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>

#include "hal/unique_fd.h"

namespace icacam::hal {

namespace {

Error osError(const std::string &what, int err)
{
    if (err == ENOSPC || err == EDQUOT) return Error::make(Errc::Full, what + ": storage is full");
    if (err == ENOENT) return Error::make(Errc::NotFound, what + ": " + std::strerror(err));
    return Error::make(Errc::Io, what + ": " + std::strerror(err));
}

Error writeAll(int fd, std::string_view data, const std::string &what)
{
    size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return osError(what, errno);
        done += size_t(n);
    }
    if (::fsync(fd) != 0) return osError(what, errno);
    return {};
}

} // namespace

Error FolderStorage::open(const std::string &folder, uint64_t quotaBytes)
{
    std::error_code ec;
    std::filesystem::create_directories(folder, ec); // a missing parent is made, as on a fresh card
    if (ec) return Error::make(Errc::Io, "storage '" + folder + "': " + ec.message());
    struct stat st {};
    if (::stat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        return Error::make(Errc::NotFound, "storage '" + folder + "' is not a folder");
    folder_ = folder;
    quota_ = quotaBytes;
    return {};
}

Error FolderStorage::checkName(std::string_view name) const
{
    if (folder_.empty()) return Error::make(Errc::Invalid, "storage not open");
    if (name.empty() || name == "." || name == ".." || name.find('/') != std::string_view::npos ||
        name.find('\0') != std::string_view::npos)
        return Error::make(Errc::Invalid, "bad storage file name");
    return {};
}

Error FolderStorage::reserve(uint64_t bytes)
{
    Result<uint64_t> free = freeBytes();
    if (!free.ok()) return free.error;
    if (bytes > free.value) return Error::make(Errc::Full, "storage is full");
    return {};
}

Error FolderStorage::append(std::string_view name, std::string_view data)
{
    if (Error e = checkName(name); !e.ok()) return e;
    if (Error e = reserve(data.size()); !e.ok()) return e;
    UniqueFd fd(::open(path(name).c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644));
    if (!fd.valid()) return osError(std::string(name), errno);
    return writeAll(fd.get(), data, std::string(name));
}

Error FolderStorage::writeAtomic(std::string_view name, std::string_view data)
{
    if (Error e = checkName(name); !e.ok()) return e;
    if (Error e = reserve(data.size()); !e.ok()) return e;
    const std::string final = path(name), tmp = final + ".tmp";
    {
        UniqueFd fd(::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
        if (!fd.valid()) return osError(std::string(name), errno);
        if (Error e = writeAll(fd.get(), data, std::string(name)); !e.ok()) {
            ::unlink(tmp.c_str());
            return e;
        }
    }
    if (::rename(tmp.c_str(), final.c_str()) != 0) return osError(std::string(name), errno);
    UniqueFd dir(::open(folder_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (dir.valid()) ::fsync(dir.get()); // makes the rename itself durable
    return {};
}

Result<std::string> FolderStorage::read(std::string_view name)
{
    if (Error e = checkName(name); !e.ok()) return {{}, e};
    UniqueFd fd(::open(path(name).c_str(), O_RDONLY | O_CLOEXEC));
    if (!fd.valid()) return {{}, osError(std::string(name), errno)};
    std::string out;
    char buf[65536];
    for (;;) {
        const ssize_t n = ::read(fd.get(), buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return {{}, osError(std::string(name), errno)};
        if (n == 0) break;
        out.append(buf, size_t(n));
    }
    return {std::move(out), {}};
}

Error FolderStorage::truncate(std::string_view name, uint64_t size)
{
    if (Error e = checkName(name); !e.ok()) return e;
    UniqueFd fd(::open(path(name).c_str(), O_WRONLY | O_CLOEXEC));
    if (!fd.valid()) return osError(std::string(name), errno);
    if (::ftruncate(fd.get(), off_t(size)) != 0 || ::fsync(fd.get()) != 0) return osError(std::string(name), errno);
    return {};
}

Error FolderStorage::remove(std::string_view name)
{
    if (Error e = checkName(name); !e.ok()) return e;
    if (::unlink(path(name).c_str()) != 0) return osError(std::string(name), errno);
    return {};
}

Result<std::vector<std::string>> FolderStorage::list()
{
    if (folder_.empty()) return Result<std::vector<std::string>>::fail(Errc::Invalid, "storage not open");
    std::unique_ptr<DIR, int (*)(DIR *)> dir(::opendir(folder_.c_str()), ::closedir);
    if (!dir) return {{}, osError(folder_, errno)};
    std::vector<std::string> names;
    while (const dirent *e = ::readdir(dir.get())) {
        const std::string n = e->d_name;
        if (n != "." && n != "..") names.push_back(n);
    }
    return {std::move(names), {}};
}

Result<uint64_t> FolderStorage::freeBytes()
{
    struct statvfs vfs {};
    if (::statvfs(folder_.c_str(), &vfs) != 0) return {0, osError(folder_, errno)};
    uint64_t free = uint64_t(vfs.f_bavail) * uint64_t(vfs.f_frsize);
    if (quota_ > 0) {
        uint64_t used = 0;
        Result<std::vector<std::string>> names = list();
        for (const std::string &n : names.value) {
            struct stat st {};
            if (::stat(path(n).c_str(), &st) == 0) used += uint64_t(st.st_size);
        }
        const uint64_t left = used >= quota_ ? 0 : quota_ - used;
        if (left < free) free = left;
    }
    return {free, {}};
}

} // namespace icacam::hal
