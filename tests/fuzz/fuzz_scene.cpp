// Fuzz target: any bytes as a slump scene file. Accepted: a scene whose every number is finite, or
// an InputError (the one-line message a user sees). Anything else — another exception, a crash, a
// hang, a sanitizer report — is a bug. Built for libFuzzer (tools/fuzz.sh) and, with
// replay_main.cpp, as a CTest that replays the corpus in every build.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "core/input_error.hpp"
#include "slump/slump_scene.hpp"

namespace {
void require_finite(double x, const char* what) {
    if (!std::isfinite(x)) throw std::logic_error(std::string("accepted scene with non-finite ") + what);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string path =
        (std::filesystem::temp_directory_path() / ("demscale_fuzz_scene_" + std::to_string(::getpid()) + ".toml")).string();
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    try {
        const auto s = demscale::slump::load_slump_scene(path);
        for (double x : {s.bottom_diameter_m, s.top_diameter_m, s.height_m, s.lift_speed_m_per_s, s.lift_height_m, s.radius_m,
                         s.fill_height_m, s.material.density, s.material.youngs_modulus, s.material.poisson_ratio,
                         s.material.restitution, s.material.friction, s.material.rolling_friction, s.liquid.surface_tension_n_per_m,
                         s.liquid.contact_angle.radians(), s.liquid.density_kg_per_m3, s.liquid.moisture_content, s.dt_s, s.gravity,
                         s.settle_time_s, s.spread_time_s, s.rest_speed_m_per_s, s.rest_duration_s, s.skin_m, s.tolerances.slump,
                         s.tolerances.spread, s.tolerances.profile})
            require_finite(x, "value");
        if (!(s.radius_m > 0 && 2 * s.radius_m < s.top_diameter_m)) throw std::logic_error("accepted a particle larger than the cone");
    } catch (const demscale::InputError&) {
        // the expected answer to a bad file
    }
    return 0;
}
