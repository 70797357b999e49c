// virtual_display.h: an Xvfb of the test's own, for machines with no display (CI). -displayfd
// makes Xvfb pick a free display number itself and write it to a pipe once it accepts
// connections, so parallel tests cannot race for a number. Stopped (by its own pid) when this
// object goes away.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace testutil {

class VirtualDisplay {
  public:
    VirtualDisplay() {
        int fds[2];
        if (pipe(fds) != 0) return;
        mPid = fork();
        if (mPid < 0) {
            close(fds[0]);
            close(fds[1]);
            return;
        }
        if (mPid == 0) {
            close(fds[0]);
            int devNull = open("/dev/null", O_WRONLY);
            if (devNull >= 0) {
                dup2(devNull, STDOUT_FILENO);
                dup2(devNull, STDERR_FILENO);
            }
            std::string fd = std::to_string(fds[1]);
            execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1920x1080x24",
                   "-nolisten", "tcp", "-noreset", static_cast<char*>(nullptr));
            _exit(127);
        }
        close(fds[1]);
        // Read up to the newline: Xvfb writes the number and the newline separately, and closing
        // the pipe early would make its second write fail (and Xvfb exit).
        std::string number;
        auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
        while (number.find('\n') == std::string::npos &&
               std::chrono::steady_clock::now() < deadline) {
            pollfd p{fds[0], POLLIN, 0};
            if (poll(&p, 1, 200) <= 0) continue;
            char buffer[16];
            ssize_t n = read(fds[0], buffer, sizeof buffer);
            if (n <= 0) break;  // Xvfb exited (not installed, or failed to start)
            number.append(buffer, static_cast<size_t>(n));
        }
        close(fds[0]);
        if (number.find('\n') == std::string::npos) {
            stop();
            return;
        }
        // Formatted, not ":" + number: GCC 12 warns falsely (-Wrestrict) on that operator+.
        char name[32];
        std::snprintf(name, sizeof name, ":%d", std::atoi(number.c_str()));
        mDisplay = name;
    }
    ~VirtualDisplay() { stop(); }
    VirtualDisplay(const VirtualDisplay&) = delete;
    VirtualDisplay& operator=(const VirtualDisplay&) = delete;

    // ":N", or empty when Xvfb did not start.
    const std::string& display() const { return mDisplay; }

  private:
    void stop() {
        if (mPid > 0) {
            kill(mPid, SIGTERM);
            waitpid(mPid, nullptr, 0);
            mPid = -1;
        }
    }

    pid_t mPid = -1;
    std::string mDisplay;
};

}  // namespace testutil
