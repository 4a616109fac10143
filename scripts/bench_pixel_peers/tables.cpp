// Same-shaped stand-ins for pbrt-v4's PMJ02BN point sets (util/pmj02tables.cpp) and
// blue-noise textures (util/bluenoise.cpp), which pbrt's headers declare `extern const`.
// Defined here, in a unit that does not see those declarations, so the driver can fill
// them before the first PMJ02BNSampler is built (a variable's linkage name carries no
// const). The sizes are pbrt's: 5 sets of 65536 points, 48 textures of 128 x 128.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace pbrt {
struct FileLoc;

// util/error.cpp's Error, which PMJ02BNSampler's constructor names for sample counts past
// 65536 (never used here): it aborts.
void Error(const FileLoc *, const char *message) {
    std::fprintf(stderr, "pbrt error (stubbed, aborting): %s\n", message);
    std::abort();
}

uint32_t pmj02bnSamples[5][65536][2];
uint16_t BlueNoiseTextures[48][128][128];
}  // namespace pbrt

extern "C" {

// Copies `points` (65536 pairs of 0.32 fractions, a PMJ02BN sequence) into every set.
void peers_set_pmj02bn_table(const uint32_t *points) {
    for (auto &set : pbrt::pmj02bnSamples)
        std::memcpy(set, points, sizeof set);
}

// Fills the blue-noise textures from `values` (48 * 128 * 128 entries).
void peers_set_blue_noise(const uint16_t *values) {
    std::memcpy(pbrt::BlueNoiseTextures, values, sizeof pbrt::BlueNoiseTextures);
}

}  // extern "C"
