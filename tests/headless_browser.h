// headless_browser.h: a real browser for the tests, Debian's Chromium run headless with its
// DevTools protocol on a pipe (--remote-debugging-pipe: fd 3 carries our commands to it, fd 4 its
// answers, each message JSON ended by a NUL). No network, no display, no GPU; as root it needs
// --no-sandbox, which CI containers are. The test drives a page with real key events
// (Input.dispatchKeyEvent) and reads it back with Runtime.evaluate.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace testutil {

class HeadlessBrowser {
  public:
    // Opens `url` (a file:// URL) in a fresh profile under `profileDir`.
    HeadlessBrowser(const std::string& url, const std::filesystem::path& profileDir) {
        int toBrowser[2], fromBrowser[2];
        if (pipe(toBrowser) != 0 || pipe(fromBrowser) != 0) throw std::runtime_error("pipe");
        mPid = fork();
        if (mPid < 0) throw std::runtime_error("fork");
        if (mPid == 0) {
            // Chromium reads fd 3 and writes fd 4.
            dup2(toBrowser[0], 3);
            dup2(fromBrowser[1], 4);
            int devNull = open("/dev/null", O_WRONLY);
            if (devNull >= 0) {
                dup2(devNull, STDOUT_FILENO);
                dup2(devNull, STDERR_FILENO);
            }
            std::string profile = "--user-data-dir=" + profileDir.string();
            execlp("chromium", "chromium", "--headless", "--no-sandbox", "--disable-gpu",
                   "--disable-dev-shm-usage", "--no-first-run", "--mute-audio",
                   "--autoplay-policy=no-user-gesture-required", "--remote-debugging-pipe",
                   "--window-size=1280,720", profile.c_str(), url.c_str(),
                   static_cast<char*>(nullptr));
            _exit(127);
        }
        close(toBrowser[0]);
        close(fromBrowser[1]);
        mOut = toBrowser[1];
        mIn = fromBrowser[0];
        attach();
    }
    ~HeadlessBrowser() {
        if (mOut >= 0) close(mOut);
        if (mIn >= 0) close(mIn);
        if (mPid > 0) {
            kill(mPid, SIGTERM);
            waitpid(mPid, nullptr, 0);
        }
    }
    HeadlessBrowser(const HeadlessBrowser&) = delete;
    HeadlessBrowser& operator=(const HeadlessBrowser&) = delete;

    // A command to the page (or, with toPage false, to the browser); its result.
    nlohmann::json call(const std::string& method, nlohmann::json params = nlohmann::json::object(),
                        bool toPage = true) {
        nlohmann::json msg = {{"id", ++mId}, {"method", method}, {"params", params}};
        if (toPage) msg["sessionId"] = mSession;
        std::string text = msg.dump();
        text.push_back('\0');
        for (size_t done = 0; done < text.size();) {
            ssize_t n = write(mOut, text.data() + done, text.size() - done);
            if (n <= 0) throw std::runtime_error("the browser closed its pipe");
            done += static_cast<size_t>(n);
        }
        for (;;) {
            nlohmann::json reply = nlohmann::json::parse(readMessage());
            if (reply.value("id", -1) != mId) continue;  // an event, or another answer
            if (reply.contains("error")) {
                throw std::runtime_error(method + ": " + reply["error"].dump());
            }
            return reply["result"];
        }
    }

    // The value of a JavaScript expression in the page.
    nlohmann::json evaluate(const std::string& expression) {
        nlohmann::json r =
            call("Runtime.evaluate", {{"expression", expression}, {"returnByValue", true}});
        if (r.contains("exceptionDetails")) throw std::runtime_error(expression + " threw");
        return r["result"].value("value", nlohmann::json());
    }

    // A key pressed and let go, as a keyboard would send it ("ArrowRight", 39).
    void press(const std::string& key, int keyCode) {
        for (const char* type : {"keyDown", "keyUp"}) {
            call("Input.dispatchKeyEvent", {{"type", type},
                                            {"key", key},
                                            {"code", key},
                                            {"windowsVirtualKeyCode", keyCode},
                                            {"nativeVirtualKeyCode", keyCode}});
        }
    }

    // Polls `expression` until it is true or `seconds` pass; whether it became true.
    bool waitFor(const std::string& expression, double seconds) {
        auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (std::chrono::steady_clock::now() < end) {
            if (evaluate(expression) == true) return true;
            usleep(50 * 1000);
        }
        return false;
    }

  private:
    // The page's target, attached in flat mode (its session id goes with each command).
    void attach() {
        auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (std::chrono::steady_clock::now() < end) {
            nlohmann::json targets = call("Target.getTargets", nlohmann::json::object(), false);
            for (const auto& t : targets["targetInfos"]) {
                if (t["type"] != "page") continue;
                nlohmann::json a = call("Target.attachToTarget",
                                        {{"targetId", t["targetId"]}, {"flatten", true}}, false);
                mSession = a["sessionId"];
                return;
            }
            usleep(100 * 1000);
        }
        throw std::runtime_error("the browser opened no page");
    }

    // The next NUL-ended message, waiting up to a minute for it.
    std::string readMessage() {
        for (;;) {
            size_t nul = mBuffer.find('\0');
            if (nul != std::string::npos) {
                std::string msg = mBuffer.substr(0, nul);
                mBuffer.erase(0, nul + 1);
                return msg;
            }
            pollfd p{mIn, POLLIN, 0};
            if (poll(&p, 1, 60000) <= 0) throw std::runtime_error("the browser did not answer");
            char chunk[65536];
            ssize_t n = read(mIn, chunk, sizeof chunk);
            if (n <= 0) throw std::runtime_error("the browser closed its pipe");
            mBuffer.append(chunk, static_cast<size_t>(n));
        }
    }

    pid_t mPid = -1;
    int mOut = -1, mIn = -1;
    int mId = 0;
    std::string mSession;
    std::string mBuffer;
};

}  // namespace testutil
