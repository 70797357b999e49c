// pcfscope: the command line (DESIGN.md section 6).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "app/cli_util.h"
#include "app/commands.h"
#include "render/image_io.h"
#include "scene/input_error.h"

namespace {

int fail(const std::string& message) {
    std::fprintf(stderr, "pcfscope: %s\n", message.c_str());
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"pcfscope: step through Percentage Closer Filtering, one shadow lookup at a time"};
    app.require_subcommand(0, 1);
    const pcf::Command commands[] = {
        pcf::addMethodsCommand(app),
        pcf::addTraceCommand(app),
        pcf::addRenderCommand(app),
        pcf::addTruthCommand(app),
        pcf::addBenchCommand(app),
        pcf::addViewCommand(app),
        pcf::addExportCommand(app),
        pcf::addVerifyCommand(app),
    };

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail(e.what());
    }

    try {
        for (const pcf::Command& c : commands) {
            if (c.sub->parsed()) return c.run();
        }
        return pcf::runMainJob();
    } catch (const pcf::UsageError& e) {
        return fail(e.what());
    } catch (const pcf::InputError& e) {
        return fail(e.what());
    } catch (const pcf::ImageError& e) {
        return fail(e.what());
    } catch (const std::filesystem::filesystem_error& e) {
        // The disk said no (full, read-only, removed under us): the outputs were taken back.
        return fail(e.path1().empty() ? e.code().message()
                                      : e.path1().string() + ": " + e.code().message());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pcfscope: internal error: %s\n", e.what());
        return 1;
    }
}
