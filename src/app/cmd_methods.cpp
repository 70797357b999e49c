#include <cstdio>
#include <string>

#include "app/commands.h"
#include "kernel/methods.h"
#include "kernel/settings.h"

namespace pcf {

Command addMethodsCommand(CLI::App& app) {
    CLI::App* sub = app.add_subcommand("methods", "list the PCF methods with what each reads");
    auto kernel = std::make_shared<int>(3);
    sub->add_option("--kernel", *kernel, "kernel size N used for the counts")
        ->check(CLI::Range(MIN_KERNEL, MAX_KERNEL));
    return {sub, [kernel] {
                std::string header = "fetches (N = " + std::to_string(*kernel) + ")";
                std::printf("%-12s %-26s %s\n", "id", header.c_str(), "what it does");
                for (const MethodInfo& m : allMethods()) {
                    int n = *kernel;
                    n = fitKernel(m.id, n);
                    FetchCounts c = fetchCounts(m.id, n);
                    auto count = [](int k, const char* what) {
                        return std::to_string(k) + " " + what + (k == 1 ? "" : "s");
                    };
                    std::string fetches = count(c.texels, "texel");
                    if (c.gathers) fetches += " in " + count(c.gathers, "gather");
                    if (c.hwTaps) fetches += " in " + count(c.hwTaps, "hw tap");
                    if (n != *kernel) fetches += " (N=" + std::to_string(n) + ")";
                    std::printf("%-12s %-26s %s\n", std::string(m.name).c_str(), fetches.c_str(),
                                std::string(m.summary).c_str());
                }
                std::printf(
                    "\nweights (pcf-naive, pcf-gather; --weights, the same fetches):\n"
                    "  box        every lookup 1/N^2 (the default)\n"
                    "  binomial   lookup (i, j) weighs C(N-1,i) C(N-1,j) / 4^(N-1)\n"
                    "  gaussian   exp(-(x^2 + y^2) / (2 sigma^2)), normalised; --sigma in texels\n"
                    "precision (hardware taps and gathers; --precision):\n"
                    "  exact      float texel position (what llvmpipe does)\n"
                    "  hw8        position rounded to 1/256 texel (8 sub-texel bits, as on "
                    "NVIDIA/AMD)\n");
                return 0;
            }};
}

}  // namespace pcf
