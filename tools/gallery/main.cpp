// ncsdk_gallery: plays the scenarios of seed 000 §2.1–§2.4 through the SDK (blocks, kernel,
// cycle driver, scope) and writes one SVG per figure — the plots of docs/blocks.md.
//
// Usage: ncsdk_gallery [output folder, default docs/gallery]
// Prints one line per figure. Exit code 0 when every figure was written and showed what it
// should (no block or axis error, limits kept, the expected end), 1 when a figure has problems
// (listed), 2 on a set-up or file error.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "scenarios.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "docs/gallery";
    gallery::Figures figures;
    gallery::dynamics(out, figures);
    gallery::override_changes(out, figures);
    gallery::stops(out, figures);
    gallery::new_end_position(out, figures);
    gallery::new_velocity_and_end_position(out, figures);
    gallery::modulo(out, figures);
    gallery::continuous_motion(out, figures);

    int bad = 0;
    for (const gallery::Figure& f : figures) {
      const bool written =
          std::filesystem::is_regular_file(f.file) && std::filesystem::file_size(f.file) > 0;
      const bool ok = written && f.ok();
      bad += ok ? 0 : 1;
      std::printf("%-4s %s  %s\n", ok ? "ok" : "FAIL", f.file.string().c_str(), f.title.c_str());
      if (!written) std::printf("       not written\n");
      for (const std::string& p : f.problems)
        std::printf("       %s\n", p.c_str());
    }
    std::printf("%zu figures, %d with problems\n", figures.size(), bad);
    return bad == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ncsdk_gallery: %s\n", e.what());
    return 2;
  }
}
