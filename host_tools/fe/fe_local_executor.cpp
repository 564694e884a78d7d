#include "host_tools/fe/fe_local_executor.h"

#include <exception>
#include <mutex>
#include <thread>

namespace icacam::host::fe {

size_t LocalExecutor::solve(const std::vector<FeCase> &cases, const GatherFn &gather)
{
    std::mutex m;
    size_t next = 0;
    auto worker = [&] {
        for (;;) {
            FeCase c;
            {
                std::lock_guard<std::mutex> l(m);
                if (next >= cases.size()) return;
                c = cases[next++];
            }
            const FeCase planned = c;
            RunResult r;
            try {
                r = runCase(c, run_);
            } catch (const std::exception &e) {
                r.status = "error";
                r.message = e.what();
            }
            std::lock_guard<std::mutex> l(m);
            printRunResult(c, r);
            gather({planned, csvRows(c, r)});
        }
    };
    std::vector<std::thread> threads;
    for (int j = 0; j < jobs_; ++j) threads.emplace_back(worker);
    for (auto &t : threads) t.join();
    return 0;
}

} // namespace icacam::host::fe
