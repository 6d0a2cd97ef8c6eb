#include "app/regression/report_files.h"

#include "io/atomic_file.h"

#include <fstream>

namespace tumble::app {

ReportImages report_images(const CheckResult& r) {
    ReportImages out;
    if (!r.image || r.run_failed) return out;
    const std::filesystem::path dir = "images";
    out.actual = dir / (r.name() + ".actual.png");
    if (r.passed) return out;
    if (r.image_outcome.expected.width > 0) out.expected = dir / (r.name() + ".expected.png");
    if (r.image_outcome.compare.same_size) out.diff = dir / (r.name() + ".diff.png");
    return out;
}

std::vector<std::filesystem::path> report_images(const std::filesystem::path& report,
                                                 const CheckResult& r) {
    std::vector<std::filesystem::path> out;
    const ReportImages images = report_images(r);
    for (const auto* p : {&images.expected, &images.actual, &images.diff})
        if (!p->empty()) out.push_back(report / *p);
    return out;
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
    io::AtomicFile file(path);
    if (!file.streaming()) io::ensure_writable_directory(path.parent_path());
    std::ofstream out(file.temp_path(), std::ios::binary | std::ios::app);
    out << text;
    out.close();
    if (!out) throw io::FileError("cannot write '" + path.string() + "'");
    file.commit();
}

} // namespace tumble::app
