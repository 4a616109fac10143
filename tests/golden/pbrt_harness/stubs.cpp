// Stand-ins for the parts of pbrt-v4's util/log.cpp and util/print.cpp that the sampler
// headers reference: fatal-error logging, warnings (util/error.cpp; the Sobol' samplers warn about sample
// counts that are not powers of two, which the driver never uses) and printf-style string
// building. They are only
// reached when a CHECK fails or an object is printed, which the driver never does; each
// aborts so that a silent difference cannot hide behind them.

#include <pbrt/util/error.h>
#include <pbrt/util/log.h>
#include <pbrt/util/print.h>

#include <cstdio>
#include <cstdlib>

namespace pbrt {

void LogFatal(LogLevel, const char *file, int line, const char *msg) {
    std::fprintf(stderr, "pbrt fatal error at %s:%d: %s\n", file, line, msg);
    std::abort();
}

void Warning(const FileLoc *, const char *message) {
    std::fprintf(stderr, "pbrt warning (stubbed, aborting): %s\n", message);
    std::abort();
}

namespace detail {

void stringPrintfRecursive(std::string *, const char *) {
    std::fprintf(stderr, "string formatting is stubbed out in this harness\n");
    std::abort();
}

std::string copyToFormatString(const char **, std::string *) {
    std::fprintf(stderr, "string formatting is stubbed out in this harness\n");
    std::abort();
}

}  // namespace detail
}  // namespace pbrt
