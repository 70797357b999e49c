// command_line.cpp: the command line (docs/user-guide.md): every subcommand, parsed, run, and
// its errors turned into one line and an exit code (app/command_line.h).
#include "app/command_line.h"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/output_files.h"
#include "base/input_error.h"
#include "render/image_io.h"
#include "video/video_writer.h"

namespace {

// One line whatever the message holds: a newline in an option value or a file name is written
// as \n (base/input_error.h oneLine).
// Staged outputs are named by their final names (app/output_files.h withFinalNames); a progress
// line still open is ended first, so the error is a line of its own.
int fail(const std::string& message) {
    pcf::endProgressLine();
    std::fprintf(stderr, "pcfscope: %s\n", pcf::oneLine(pcf::withFinalNames(message)).c_str());
    return 2;
}

// One rule for every option: a value given empty (`--size ""`, `-o ""`) is refused, never read
// as "the default". Flags take no value and are not asked.
void refuseEmptyValues(const CLI::App& app) {
    for (const CLI::Option* option : app.get_options()) {
        if (option->get_type_size() == 0 || option->count() == 0) continue;
        for (const std::string& value : option->results()) {
            if (value.empty()) {
                std::string name = option->get_name();
                if (name.empty()) name = option->get_single_name();
                throw pcf::UsageError(name + " needs a value; an empty one is refused");
            }
        }
    }
    for (const CLI::App* sub : app.get_subcommands()) refuseEmptyValues(*sub);
}

}  // namespace

int pcf::runCommandLine(int argc, char** argv) {
    // Before any thread starts (app/output_files.h): Ctrl-C leaves no half output.
    pcf::installInterruptCleanup();
    CLI::App app{"pcfscope: step through Percentage Closer Filtering, one shadow lookup at a time"};
    app.require_subcommand(0, 1);
    const pcf::Command commands[] = {
        pcf::addMethodsCommand(app),  pcf::addTraceCommand(app),   pcf::addRenderCommand(app),
        pcf::addTruthCommand(app),    pcf::addBenchCommand(app),   pcf::addStabilityCommand(app),
        pcf::addViewCommand(app),     pcf::addExportCommand(app),  pcf::addVerifyCommand(app),
        pcf::addLessonCommand(app),   pcf::addAnimateCommand(app), pcf::addPickCommand(app),
        pcf::addExerciseCommand(app), pcf::addAdviseCommand(app),
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
        refuseEmptyValues(app);
        int code = -1;
        for (const pcf::Command& c : commands) {
            if (c.sub->parsed()) code = c.run();
        }
        if (code < 0) code = pcf::runMainJob();
        // Standard output is a write like any other (redirected to a file on a full disk):
        // what could not be written is an error, not a success.
        if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
            return fail(std::string("cannot write to standard output (") + std::strerror(errno) +
                        ")");
        }
        return code;
    } catch (const pcf::UsageError& e) {
        return fail(e.what());
    } catch (const pcf::InputError& e) {
        return fail(e.what());
    } catch (const pcf::ImageError& e) {
        return fail(e.what());
    } catch (const pcf::VideoError& e) {
        return fail(e.what());
    } catch (const std::filesystem::filesystem_error& e) {
        // The disk said no (full, read-only, removed under us): the outputs were taken back.
        return fail(e.path1().empty() ? e.code().message()
                                      : e.path1().string() + ": " + e.code().message());
    } catch (const std::exception& e) {
        pcf::endProgressLine();
        std::fprintf(stderr, "pcfscope: internal error: %s\n", pcf::oneLine(e.what()).c_str());
        return 1;
    }
}
