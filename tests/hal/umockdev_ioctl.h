#pragma once
// The argument of an ioctl a umockdev handler intercepts, resolved in the client's memory as
// a T; nullptr when the pointer is bad or the data shorter than T (the handler answers EFAULT).
#include <umockdev.h>

#include <cstddef>

namespace icacam::test {

template <typename T> T *ioctlArg(UMockdevIoctlClient *client)
{
    UMockdevIoctlData *arg = umockdev_ioctl_client_get_arg(client);
    UMockdevIoctlData *d = arg ? umockdev_ioctl_data_resolve(arg, 0, sizeof(T), nullptr) : nullptr;
    return d && size_t(d->data_len) >= sizeof(T) ? reinterpret_cast<T *>(d->data) : nullptr;
}

} // namespace icacam::test
