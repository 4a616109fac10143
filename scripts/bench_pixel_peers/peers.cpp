// The C++ side of the pixel-sampler bench (scripts/bench_pixel_peers.sh): pbrt-v4's and
// OpenQMC's samplers on the bench workload, behind a C interface that the Rust driver
// (examples/pixel_peers.rs) links.
//
// Workload: a 256 x 256 image, 16 samples a pixel; per sample two 2D draws as float (pbrt:
// StartPixelSample(p, i, 0), then Get2D twice; OpenQMC: one 4D drawSample of the sample's
// root domain, its 4D unit). A pixel's 64 floats go to a stack buffer that an empty asm
// statement publishes (the compiler must produce them), and, when `out` is not null, are
// copied to out[64 * (y * 256 + x) ..] for the driver's bit-for-bit comparison.
//
// pbrt-v4's PMJ02BN and blue-noise tables are data files (util/pmj02tables.cpp,
// util/bluenoise.cpp); tables.cpp holds same-shaped tables that the driver fills at
// start-up instead, which changes the values, not the work.

#include <pbrt/samplers.h>
#include <pbrt/util/bluenoise.h>
#include <pbrt/util/pmj02tables.h>

#include <oqmc/oqmc.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace {

constexpr int kSide = 256;
constexpr int kSpp = 16;

inline void Publish(const float *p) { asm volatile("" : : "r"(p) : "memory"); }

template <typename S>
void RunPbrt(S &s, float *out) {
    alignas(64) float px[kSpp * 4];
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            pbrt::Point2i p(x, y);
            for (int i = 0; i < kSpp; ++i) {
                s.StartPixelSample(p, i, 0);
                pbrt::Point2f a = s.Get2D();
                pbrt::Point2f b = s.Get2D();
                px[4 * i] = a.x;
                px[4 * i + 1] = a.y;
                px[4 * i + 2] = b.x;
                px[4 * i + 3] = b.y;
            }
            Publish(px);
            if (out)
                std::memcpy(out + 64 * (y * kSide + x), px, sizeof px);
        }
}

template <typename S>
void RunOqmc(const void *cache, float *out) {
    alignas(64) float px[kSpp * 4];
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            for (int i = 0; i < kSpp; ++i) {
                S s(x, y, 0, i, cache);
                s.template drawSample<4>(px + 4 * i);
            }
            Publish(px);
            if (out)
                std::memcpy(out + 64 * (y * kSide + x), px, sizeof px);
        }
}

template <typename S>
struct Cached {
    std::vector<unsigned char> cache;
    Cached() : cache(S::cacheSize > 0 ? S::cacheSize : 1) {
        S::initialiseCache(cache.data());
    }
};

}  // namespace

extern "C" {

// Runs one peer sampler over the workload; returns 0, or -1 for an unknown id.
// Ids: 0 pbrt ZSobol, 1 pbrt PaddedSobol, 2 pbrt Sobol (image plane), 3 pbrt PMJ02BN,
// 4 pbrt Halton, 5 pbrt Stratified (4 x 4, jittered), 6 pbrt Independent (all seed 0,
// FastOwen for the Sobol' samplers, PermuteDigits for Halton); 10 OpenQMC Sobol,
// 11 SobolBn, 12 Pmj, 13 PmjBn, 14 Lattice, 15 LatticeBn.
int peers_run(int id, float *out) {
    using namespace pbrt;
    const Point2i res(kSide, kSide);
    switch (id) {
    case 0: {
        static ZSobolSampler s(kSpp, res, RandomizeStrategy::FastOwen, 0);
        RunPbrt(s, out);
        return 0;
    }
    case 1: {
        static PaddedSobolSampler s(kSpp, RandomizeStrategy::FastOwen, 0);
        RunPbrt(s, out);
        return 0;
    }
    case 2: {
        static SobolSampler s(kSpp, res, RandomizeStrategy::FastOwen, 0);
        RunPbrt(s, out);
        return 0;
    }
    case 3: {
        static PMJ02BNSampler s(kSpp, 0);
        RunPbrt(s, out);
        return 0;
    }
    case 4: {
        static HaltonSampler s(kSpp, res, RandomizeStrategy::PermuteDigits, 0);
        RunPbrt(s, out);
        return 0;
    }
    case 5: {
        static StratifiedSampler s(4, 4, true, 0);
        RunPbrt(s, out);
        return 0;
    }
    case 6: {
        static IndependentSampler s(kSpp, 0);
        RunPbrt(s, out);
        return 0;
    }
    case 10: {
        static Cached<oqmc::SobolSampler> c;
        RunOqmc<oqmc::SobolSampler>(c.cache.data(), out);
        return 0;
    }
    case 11: {
        static Cached<oqmc::SobolBnSampler> c;
        RunOqmc<oqmc::SobolBnSampler>(c.cache.data(), out);
        return 0;
    }
    case 12: {
        static Cached<oqmc::PmjSampler> c;
        RunOqmc<oqmc::PmjSampler>(c.cache.data(), out);
        return 0;
    }
    case 13: {
        static Cached<oqmc::PmjBnSampler> c;
        RunOqmc<oqmc::PmjBnSampler>(c.cache.data(), out);
        return 0;
    }
    case 14: {
        static Cached<oqmc::LatticeSampler> c;
        RunOqmc<oqmc::LatticeSampler>(c.cache.data(), out);
        return 0;
    }
    case 15: {
        static Cached<oqmc::LatticeBnSampler> c;
        RunOqmc<oqmc::LatticeBnSampler>(c.cache.data(), out);
        return 0;
    }
    default:
        return -1;
    }
}

}  // extern "C"
