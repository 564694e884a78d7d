// The web server goes on while a login is checked: a login held on the worker (its Argon2id
// check takes a third of a second on purpose) does not stop a page from being served, and
// logins beyond the ones the worker holds are refused at once. Ordering, not timing: the
// check is held until the test has seen the page.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "firmware/net/aim_exchange.h"
#include "firmware/net/command_inbox.h"
#include "firmware/net/journal_tail.h"
#include "firmware/net/line_exchange.h"
#include "firmware/net/web_auth.h"
#include "firmware/net/web_server.h"
#include "tests/support/temp_dir.h"

namespace icacam::fw::net {
namespace {

// A login check that waits until the test lets it go, and says how many have begun.
struct HeldCheck {
    std::mutex m;
    std::condition_variable cv;
    int begun = 0;
    bool released = false;

    HttpResponse operator()(const HttpRequest &)
    {
        std::unique_lock<std::mutex> lock(m);
        ++begun;
        cv.notify_all();
        cv.wait(lock, [this] { return released; });
        return json("{\"type\":\"login\"}\n");
    }
    bool waitBegun(int n)
    {
        std::unique_lock<std::mutex> lock(m);
        return cv.wait_for(lock, std::chrono::seconds(20), [&] { return begun >= n; });
    }
    void release()
    {
        std::lock_guard<std::mutex> lock(m);
        released = true;
        cv.notify_all();
    }
};

int connectTo(int port)
{
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(uint16_t(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr *>(&a), sizeof a) != 0) {
        ::close(fd);
        return -1;
    }
    return fd;
}

void sendAll(int fd, const std::string &s)
{
    size_t off = 0;
    while (off < s.size()) {
        const ssize_t n = ::send(fd, s.data() + off, s.size() - off, MSG_NOSIGNAL);
        if (n <= 0) return;
        off += size_t(n);
    }
}

// The whole response (the server closes after it), or what came within waitMs.
std::string readAll(int fd, int waitMs)
{
    std::string out;
    char buf[4096];
    for (;;) {
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, waitMs) <= 0) return out;
        const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
        if (n <= 0) return out;
        out.append(buf, size_t(n));
    }
}

std::string loginRequest()
{
    const std::string body = "{\"password\":\"secret\",\"user\":\"alice\"}";
    return "POST /api/login HTTP/1.1\r\nHost: x\r\nConnection: close\r\nContent-Type: application/json\r\n"
           "Content-Length: " +
           std::to_string(body.size()) + "\r\n\r\n" + body;
}

struct Server {
    test::TempDir dir;
    JournalTail journal{dir.path + "/journal.jsonl"};
    CommandInbox inbox;
    LineExchange lines;
    AimExchange aim;
    WebAuth auth{""};
    WebApi api{WebContext{journal, dir.path, inbox, lines, aim, auth, true}};
    HeldCheck held;
    WebServer server{api, [this](const HttpRequest &r) { return held(r); }};
};

TEST(WebLogin, APageIsServedWhileALoginIsChecked)
{
    Server s;
    ASSERT_TRUE(s.server.start({"127.0.0.1", 0, "", ""}).ok());
    const int login = connectTo(s.server.port());
    ASSERT_GE(login, 0);
    sendAll(login, loginRequest());
    ASSERT_TRUE(s.held.waitBegun(1)); // the login is on the worker, held there
    const int page = connectTo(s.server.port());
    ASSERT_GE(page, 0);
    sendAll(page, "GET /api/session HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
    const std::string answer = readAll(page, 20000);
    ::close(page);
    EXPECT_NE(answer.find("200 OK"), std::string::npos) << answer;
    EXPECT_NE(answer.find("logged_in"), std::string::npos) << answer;
    EXPECT_EQ(readAll(login, 0), ""); // still being checked
    s.held.release();
    const std::string loggedIn = readAll(login, 20000);
    ::close(login);
    EXPECT_NE(loggedIn.find("200 OK"), std::string::npos) << loggedIn;
    EXPECT_NE(loggedIn.find("\"login\""), std::string::npos) << loggedIn;
    s.server.stop();
}

TEST(WebLogin, LoginsBeyondTheQueueAreRefusedAtOnce)
{
    Server s;
    ASSERT_TRUE(s.server.start({"127.0.0.1", 0, "", ""}).ok());
    std::vector<int> held;
    held.push_back(connectTo(s.server.port()));
    sendAll(held.back(), loginRequest());
    ASSERT_TRUE(s.held.waitBegun(1));
    for (size_t i = 0; i < LoginQueue::kWaiting; ++i) {
        held.push_back(connectTo(s.server.port()));
        sendAll(held.back(), loginRequest());
    }
    // One more than the worker holds: refused while the others still wait.
    const int extra = connectTo(s.server.port());
    sendAll(extra, loginRequest());
    const std::string refused = readAll(extra, 20000);
    ::close(extra);
    EXPECT_NE(refused.find("503"), std::string::npos) << refused;
    EXPECT_NE(refused.find("busy"), std::string::npos) << refused;
    s.held.release();
    int answered = 0;
    for (int fd : held) {
        answered += readAll(fd, 20000).find("200 OK") != std::string::npos ? 1 : 0;
        ::close(fd);
    }
    EXPECT_EQ(answered, int(held.size()));
    s.server.stop();
}

TEST(WebLogin, StoppingWithLoginsWaitingAnswersThem)
{
    Server s;
    ASSERT_TRUE(s.server.start({"127.0.0.1", 0, "", ""}).ok());
    const int first = connectTo(s.server.port());
    sendAll(first, loginRequest());
    ASSERT_TRUE(s.held.waitBegun(1));
    const int second = connectTo(s.server.port());
    sendAll(second, loginRequest());
    std::thread releaser([&] {
        s.held.release(); // the one being checked finishes; the waiting one is not checked
    });
    s.server.stop();
    releaser.join();
    ::close(first);
    ::close(second);
}

} // namespace
} // namespace icacam::fw::net
