// Golden values for qmckit's pixel samplers from pbrt-v4's own sampler classes.
//
// Built by build.sh against a pbrt-v4 checkout: it includes <pbrt/samplers.h> and links
// pbrt's util/primes.cpp, util/lowdiscrepancy.cpp, util/sobolmatrices.cpp, util/pstd.cpp,
// the HaltonSampler constructor cut out of samplers.cpp, and stubs.cpp (logging and string
// formatting, never reached on the paths exercised here).
//
// For every configuration (sampler, randomization, image, samples per pixel, seed) and
// every pixel sample (x, y, i) of the whole image (of the SPARSE pixels for a configuration
// marked "sparse") it prints one line of f32 bit patterns
// (8 hex digits each), in this order:
//   random access, for each start dimension d in STARTS (a fresh StartPixelSample(p, i, d)
//     before each call): Get1D; Get2D (x, y)
//   GetPixel2D (x, y) after StartPixelSample(p, i, 0), then after StartPixelSample(p, i, 5)
//   stream A: StartPixelSample(p, i, 0), then PATTERN_A in order (every value)
//   stream B: StartPixelSample(p, i, 1), then PATTERN_B in order
// The layout is repeated in the header of the output, which the Rust test reads.

#include <pbrt/samplers.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace pbrt;

static const int STARTS[] = {0, 1, 2, 5, 999};
// 'p' GetPixel2D, '1' Get1D, '2' Get2D.
static const char *PATTERN_A = "p212112";
static const char *PATTERN_B = "12p12";

static uint32_t Bits(Float f) {
    static_assert(sizeof(Float) == 4, "pbrt must be built with float");
    uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

static void Put(std::string &line, Float f) {
    char buf[16];
    std::snprintf(buf, sizeof buf, " %08x", Bits(f));
    line += buf;
}

template <typename S>
static void Draw(S &s, char c, std::string &line) {
    if (c == '1') {
        Put(line, s.Get1D());
    } else {
        Point2f u = (c == '2') ? s.Get2D() : s.GetPixel2D();
        Put(line, u.x);
        Put(line, u.y);
    }
}

// The pixels of a "sparse" configuration (an image too large to print whole): corners,
// both sides of Halton's 128-pixel period and the far corner.
static const int SPARSE[][2] = {{0, 0}, {1, 0}, {127, 71}, {128, 0}, {129, 72},
                                {255, 199}, {256, 128}, {299, 130}, {299, 199}};

template <typename S>
static void Emit(const char *id, S &s, int w, int h, int spp, bool sparse) {
    std::vector<Point2i> pixels;
    if (sparse) {
        for (auto &p : SPARSE)
            pixels.push_back(Point2i(p[0], p[1]));
    } else {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                pixels.push_back(Point2i(x, y));
    }
    for (Point2i p : pixels)
            for (int i = 0; i < spp; ++i) {
                int x = p.x, y = p.y;
                std::string line = std::string(id) + " " + std::to_string(x) + " " +
                                   std::to_string(y) + " " + std::to_string(i);
                for (int d : STARTS) {
                    s.StartPixelSample(p, i, d);
                    Draw(s, '1', line);
                    s.StartPixelSample(p, i, d);
                    Draw(s, '2', line);
                }
                for (int d : {0, 5}) {
                    s.StartPixelSample(p, i, d);
                    Draw(s, 'p', line);
                }
                s.StartPixelSample(p, i, 0);
                for (const char *c = PATTERN_A; *c; ++c)
                    Draw(s, *c, line);
                s.StartPixelSample(p, i, 1);
                for (const char *c = PATTERN_B; *c; ++c)
                    Draw(s, *c, line);
                std::printf("%s\n", line.c_str());
            }
}

static RandomizeStrategy Strategy(const std::string &r) {
    if (r == "none")
        return RandomizeStrategy::None;
    if (r == "permutedigits")
        return RandomizeStrategy::PermuteDigits;
    if (r == "fastowen")
        return RandomizeStrategy::FastOwen;
    return RandomizeStrategy::Owen;
}

struct Config {
    std::string sampler, randomization;
    int w, h, spp, seed;
    int xs, ys;  // stratified only
    bool sparse = false;  // only the SPARSE pixels
};

static void Run(int n, const Config &c) {
    std::string id = "c" + std::to_string(n);
    std::printf("config %s %s %s %d %d %d %d", id.c_str(), c.sampler.c_str(),
                c.randomization.c_str(), c.w, c.h, c.spp, c.seed);
    if (c.sampler == "stratified")
        std::printf(" %d %d", c.xs, c.ys);
    if (c.sparse)
        std::printf(" sparse");
    std::printf("\n");
    Point2i res(c.w, c.h);
    RandomizeStrategy r = Strategy(c.randomization);
    if (c.sampler == "zsobol") {
        ZSobolSampler s(c.spp, res, r, c.seed);
        Emit(id.c_str(), s, c.w, c.h, c.spp, c.sparse);
    } else if (c.sampler == "padded-sobol") {
        PaddedSobolSampler s(c.spp, r, c.seed);
        Emit(id.c_str(), s, c.w, c.h, c.spp, c.sparse);
    } else if (c.sampler == "image-sobol") {
        SobolSampler s(c.spp, res, r, c.seed);
        Emit(id.c_str(), s, c.w, c.h, c.spp, c.sparse);
    } else if (c.sampler == "halton") {
        HaltonSampler s(c.spp, res, r, c.seed);
        Emit(id.c_str(), s, c.w, c.h, c.spp, c.sparse);
    } else {
        StratifiedSampler s(c.xs, c.ys, c.randomization == "jitter", c.seed);
        Emit(id.c_str(), s, c.w, c.h, c.xs * c.ys, c.sparse);
    }
}

int main() {
    std::printf("# starts");
    for (int d : STARTS)
        std::printf(" %d", d);
    std::printf("\n# pattern-a %s\n# pattern-b %s\n", PATTERN_A, PATTERN_B);
    std::vector<Config> configs;
    const char *sobolRand[] = {"none", "permutedigits", "fastowen", "owen"};
    // Set A: a 4 x 3 image, 4 samples a pixel, seed 0, every randomization.
    for (const char *s : {"zsobol", "padded-sobol", "image-sobol"})
        for (const char *r : sobolRand)
            configs.push_back({s, r, 4, 3, 4, 0, 0, 0});
    for (const char *r : {"none", "permutedigits", "owen"})
        configs.push_back({"halton", r, 4, 3, 4, 0, 0, 0});
    configs.push_back({"stratified", "jitter", 4, 3, 4, 0, 2, 2});
    configs.push_back({"stratified", "none", 4, 3, 4, 0, 2, 2});
    // Set B: a 4 x 4 image, 2 samples a pixel (odd log2 for ZSobol), seed 7.
    for (const char *s : {"zsobol", "padded-sobol", "image-sobol"})
        for (const char *r : {"fastowen", "owen"})
            configs.push_back({s, r, 4, 4, 2, 7, 0, 0});
    configs.push_back({"halton", "permutedigits", 4, 4, 2, 7, 0, 0});
    configs.push_back({"halton", "owen", 4, 4, 2, 7, 0, 0});
    configs.push_back({"stratified", "jitter", 4, 4, 2, 7, 2, 1});
    // Set C: a 3 x 3 image, sample counts that are not powers of two, a larger odd seed.
    configs.push_back({"halton", "permutedigits", 3, 3, 3, 12345, 0, 0});
    configs.push_back({"stratified", "jitter", 3, 3, 3, 12345, 3, 1});
    configs.push_back({"stratified", "none", 3, 3, 6, 12345, 2, 3});
    configs.push_back({"zsobol", "owen", 3, 3, 8, 12345, 0, 0});
    // Set D: a 300 x 200 image, 2 samples a pixel, only the SPARSE pixels (Halton's 128-pixel period, Sobol'
    // grids of side 512).
    for (Config c : std::vector<Config>{{"zsobol", "fastowen", 300, 200, 2, 3, 0, 0},
                                        {"padded-sobol", "owen", 300, 200, 2, 3, 0, 0},
                                        {"image-sobol", "fastowen", 300, 200, 2, 3, 0, 0},
                                        {"halton", "permutedigits", 300, 200, 2, 3, 0, 0},
                                        {"halton", "owen", 300, 200, 2, 3, 0, 0},
                                        {"stratified", "jitter", 300, 200, 2, 3, 2, 1}}) {
        c.sparse = true;
        configs.push_back(c);
    }
    for (size_t n = 0; n < configs.size(); ++n)
        Run(int(n), configs[n]);
    return 0;
}
