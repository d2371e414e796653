#pragma once
// The report's plot drawn by gnuplot (Debian gnuplot-nox), from a script generated here and
// kept beside the report (DIR/error_vs_time.gp; `gnuplot -c error_vs_time.gp out.png` redraws
// it). The image gnuplot writes is read back through OpenImageIO, so what the report writes
// is an image OIIO can read, like every other.
#include <OpenImageIO/imagebuf.h>

#include <string>

#include "plot_layout.h"

namespace ocean::report {

// The gnuplot program on PATH, or "" when there is none.
std::string findGnuplot();

// The script that draws `layout` to the PNG named by its first argument (ARG1).
std::string gnuplotScript(const PlotLayout& layout);

// Writes `scriptPath`, runs `gnuplot` on it into a temporary PNG beside it and reads that
// back into `image`; false with a one-line reason (gnuplot's first error line) otherwise.
bool drawWithGnuplot(const std::string& gnuplot, const PlotLayout& layout,
                     const std::string& scriptPath, OIIO::ImageBuf& image, std::string& error);

}  // namespace ocean::report
