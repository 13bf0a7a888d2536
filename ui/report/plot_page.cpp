#include "ui/report/plot_page.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <plplot/plplot.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <system_error>
#include <type_traits>

namespace nibrig::ui::report::detail {

namespace {

static_assert(std::is_same_v<PLINT, int>, "PlotPage keeps PLplot's error code in an int");
static_assert(std::is_same_v<PLFLT, double>, "figures pass double arrays to PLplot");

// PLplot keeps its streams, drivers and colour maps in process-wide state: one figure at a time.
std::mutex& plplot_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Where PLplot looks for its dynamically loaded drivers: $PLPLOT_DRV_DIR, else the folder its build
// installed them in, <libdir>/plplot<version>/drivers beside libplplot itself.
std::filesystem::path plplot_driver_dir() {
  if (const char* env = std::getenv("PLPLOT_DRV_DIR"); env != nullptr && *env != '\0') return env;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&c_plinit), &info) != 0 && info.dli_fname != nullptr) {
    return std::filesystem::path(info.dli_fname).parent_path() / ("plplot" PLPLOT_VERSION) /
           "drivers";
  }
  return {};
}

std::string figure(const std::string& name) {
  return "figure " + (name.empty() ? std::string("(untitled)") : "\"" + name + "\"");
}

constexpr const char* install_hint = "install plplot-driver-cairo (Debian) for PNG figures";

}  // namespace

void require_pngcairo() {
  const auto dir = plplot_driver_dir();
  std::error_code ec;
  std::string module;
  if (!dir.empty() && std::filesystem::is_directory(dir, ec)) {
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      if (entry.path().extension() != ".driver_info") continue;
      std::ifstream info(entry.path());
      std::string line;
      while (std::getline(info, line)) {
        // device:description:interactive:module:sequence:tag
        if (line.rfind("pngcairo:", 0) != 0) continue;
        std::size_t field_start = 0;
        for (int field = 0; field < 3 && field_start != std::string::npos; ++field) {
          field_start = line.find(':', field_start);
          if (field_start != std::string::npos) ++field_start;
        }
        if (field_start != std::string::npos) {
          module = line.substr(field_start, line.find(':', field_start) - field_start);
        }
      }
      if (!module.empty()) break;
    }
  }
  if (module.empty()) {
    throw std::runtime_error("PLplot has no pngcairo device (no pngcairo entry in " +
                             (dir.empty() ? std::string("its driver folder") : dir.string()) +
                             "): " + install_hint);
  }
  const auto library = dir / (module + ".so");
  // Loaded for good (PLplot loads it next anyway): unloading cairo and pango again is asking for
  // trouble.
  void* handle = dlopen(library.c_str(), RTLD_LAZY | RTLD_LOCAL | RTLD_NODELETE);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error("PLplot's pngcairo device cannot be loaded from " + library.string() +
                             ": " + (why != nullptr ? why : "unknown error") + "; " + install_hint);
  }
  dlclose(handle);
}

PlotPage::PlotPage(std::string name, const std::filesystem::path& png, int width_px, int height_px)
    : lock_(plplot_mutex()),
      name_(std::move(name)),
      png_(png),
      width_(width_px),
      height_(height_px) {
  require_pngcairo();

  // The temporary file sits beside the target (model/io/atomic_file.hpp: a link is followed, a
  // device is written as a stream). Creating it here also proves the folder writable: PLplot
  // itself ends the process when it cannot open its output file.
  target_ = model::io::output_target(png);
  const auto candidate = model::io::temporary_beside(target_);
  // O_EXCL: never reuse a file someone else made; 0666 lets the umask decide, as for any file.
  const int fd = open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    throw std::runtime_error(figure(name_) + ": cannot write " + png.string() +
                             ": cannot create " + candidate.string() + ": " + std::strerror(errno));
  }
  close(fd);
  temporary_ = candidate;

  plgstrm(&previous_stream_);
  plmkstrm(&stream_);
  stream_open_ = true;
  plsError(&error_code_, error_message_);
  plsdev("pngcairo");
  plsfnam(temporary_.c_str());
  plspage(0.0, 0.0, width_, height_, 0, 0);
  plscolbg(255, 255, 255);
  plsori(0);
  plsdiori(0.0);
  plinit();

  std::vector<PLINT> r, g, b;
  for (const auto& c : viridis()) {
    r.push_back(c.r);
    g.push_back(c.g);
    b.push_back(c.b);
  }
  plscmap1n(static_cast<PLINT>(r.size()));
  plscmap1(r.data(), g.data(), b.data(), static_cast<PLINT>(r.size()));
  plscmap0n(16);
  plscol0(0, 255, 255, 255);
  pladv(0);
  plsfont(PL_FCI_SANS, PL_FCI_UPRIGHT, PL_FCI_MEDIUM);
  pllsty(1);
  page_space();
  colour({0, 0, 0});
  line_width(1.0);
}

PlotPage::~PlotPage() {
  finish_stream();
  if (!committed_ && !temporary_.empty()) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void PlotPage::finish_stream() {
  if (!stream_open_) return;
  plsstrm(stream_);
  plend1();
  plsstrm(previous_stream_);  // hand back whatever stream the rest of the program had selected
  stream_open_ = false;
}

void PlotPage::page_space() {
  PLFLT xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  plgspa(&xmin, &xmax, &ymin, &ymax);
  plsvpa(0.0, xmax - xmin, 0.0, ymax - ymin);
  plwind(0.0, width_, 0.0, height_);
}

void PlotPage::colour(Rgb c, double alpha) {
  plscol0a(15, c.r, c.g, c.b, alpha);
  plcol0(15);
}

void PlotPage::line_width(double px) { plwidth(px); }

void PlotPage::dashes(const std::vector<double>& on_off_px) {
  if (on_off_px.size() < 2) {
    pllsty(1);
    return;
  }
  // plstyl counts in micrometres on the page.
  PLFLT xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  plgspa(&xmin, &xmax, &ymin, &ymax);
  const double um_per_px = 1000.0 * (xmax - xmin) / width_;
  std::vector<PLINT> marks, spaces;
  for (std::size_t i = 0; i + 1 < on_off_px.size(); i += 2) {
    marks.push_back(static_cast<PLINT>(std::lround(on_off_px[i] * um_per_px)));
    spaces.push_back(static_cast<PLINT>(std::lround(on_off_px[i + 1] * um_per_px)));
  }
  plstyl(static_cast<PLINT>(marks.size()), marks.data(), spaces.data());
}

void PlotPage::polyline(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() < 2) return;
  plline(static_cast<PLINT>(x.size()), x.data(), y.data());
}

void PlotPage::segment(double x0, double y0, double x1, double y1) { pljoin(x0, y0, x1, y1); }

void PlotPage::fill(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() < 3) return;
  plfill(static_cast<PLINT>(x.size()), x.data(), y.data());
}

void PlotPage::rectangle(double x0, double y0, double x1, double y1) {
  fill({x0, x1, x1, x0}, {y0, y0, y1, y1});
}

void PlotPage::disc(double x, double y, double radius) {
  constexpr int n = 36;
  std::vector<double> xs(n), ys(n);
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    xs[i] = x + radius * std::cos(a);
    ys[i] = y + radius * std::sin(a);
  }
  fill(xs, ys);
}

void PlotPage::text(double x, double y, double angle_deg, double just, double cap_px,
                    const std::string& s) {
  if (s.empty()) return;
  PLFLT xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  plgspa(&xmin, &xmax, &ymin, &ymax);
  const double mm_per_px = (xmax - xmin) / width_;
  plschr(cap_px * mm_per_px, 1.0);
  const double a = angle_deg * std::numbers::pi / 180.0;
  plptex(x, y, std::cos(a), std::sin(a), just, s.c_str());
}

void PlotPage::cells(double x0, double y0, double x1, double y1, const std::vector<double>& x_edges,
                     const std::vector<double>& y_edges,
                     const std::vector<std::vector<double>>& t) {
  const auto nx = static_cast<PLINT>(x_edges.size() - 1);
  const auto ny = static_cast<PLINT>(y_edges.size() - 1);
  // PLplot wants the image column-major (idata[ix][iy]).
  std::vector<std::vector<double>> columns(static_cast<std::size_t>(nx),
                                           std::vector<double>(static_cast<std::size_t>(ny)));
  std::vector<const PLFLT*> rows;
  for (PLINT i = 0; i < nx; ++i) {
    for (PLINT j = 0; j < ny; ++j) columns[i][j] = t[j][i];
    rows.push_back(columns[i].data());
  }
  PLFLT xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  plgspa(&xmin, &xmax, &ymin, &ymax);
  const double mm_per_px = (xmax - xmin) / width_;
  plsvpa(x0 * mm_per_px, x1 * mm_per_px, y0 * mm_per_px, y1 * mm_per_px);
  plwind(x_edges.front(), x_edges.back(), y_edges.front(), y_edges.back());
  std::vector<double> xg = x_edges, yg = y_edges;
  PLcGrid grid{};
  grid.xg = xg.data();
  grid.yg = yg.data();
  grid.nx = nx + 1;
  grid.ny = ny + 1;
  // Corner (i, j) of the cell grid is passed to pltr1 as (i, j), which looks up the edges.
  plimagefr(rows.data(), nx, ny, 0.0, nx, 0.0, ny, 0.0, 1.0, 0.0, 1.0, pltr1, &grid);
  page_space();
}

namespace {

// Cairo does not report a failed write (a full disk) to PLplot: a PNG is whole only when it ends
// with its IEND chunk.
bool png_is_whole(const std::filesystem::path& file) {
  static constexpr unsigned char kIend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
  std::ifstream in(file, std::ios::binary);
  in.seekg(-12, std::ios::end);
  char tail[12] = {};
  return in.read(tail, 12) && std::memcmp(tail, kIend, 12) == 0;
}

}  // namespace

void PlotPage::commit() {
  finish_stream();
  if (error_code_ != 0) {
    throw std::runtime_error(figure(name_) + ": PLplot failed: " + error_message_);
  }
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(temporary_, ec);
  if (ec || bytes == 0) {
    throw std::runtime_error(figure(name_) + ": PLplot wrote nothing to " + temporary_.string());
  }
  if (!png_is_whole(temporary_)) {
    throw std::runtime_error(figure(name_) + ": cannot write " + png_.string() + ": the image was cut off after " +
                             std::to_string(bytes) + " bytes (is the disk full?)");
  }
  try {
    model::io::commit_output(temporary_, target_);
  } catch (const std::exception& e) {
    committed_ = true;  // commit_output removed the temporary
    throw std::runtime_error(figure(name_) + ": cannot write " + png_.string() + ": " + e.what());
  }
  committed_ = true;
}

}  // namespace nibrig::ui::report::detail
