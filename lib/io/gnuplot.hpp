// Renders a gnuplot script to PNG (pngcairo). The script reads `outfile` if set, so we can
// point it at a temporary file and rename only a complete image over the target.
#pragma once

#include <filesystem>
#include <string>

namespace demscale::io {

// Text for a double-quoted string in an enhanced-mode script: _ ^ @ & { } shown literally.
std::string gnuplot_literal(const std::string& text);

// True when a gnuplot executable is on PATH.
bool gnuplot_available();

// Runs `gnuplot` in the script's directory with outfile = a temporary beside png_target,
// then renames it over png_target. Throws std::runtime_error (with gnuplot's exit status) on failure.
void render_gnuplot(const std::filesystem::path& script, const std::filesystem::path& png_target);

}  // namespace demscale::io
