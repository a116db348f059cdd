#include "lib/report/report_files.hpp"

#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "lib/report/map_picture.hpp"
#include "lib/report/report_json.hpp"
#include "lib/report/weights_picture.hpp"

namespace beft::report {
namespace {

void writePng(const cv::Mat& image, const std::filesystem::path& path) {
  bool written = false;
  try {
    written = cv::imwrite(path.string(), image);
  } catch (const cv::Exception& e) {
    throw ReportError(path.string() + ": cannot write the picture: " + e.what());
  }
  if (!written) throw ReportError(path.string() + ": cannot write the picture");
}

}  // namespace

void writeReportFiles(const RunRecord& record, const RunReport& report, const std::string& out_dir) {
  const std::filesystem::path dir(out_dir);
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir))
    throw ReportError(out_dir + ": cannot create the output folder" + (error ? ": " + error.message() : ""));

  const auto json_path = dir / "report.json";
  std::ofstream json_file(json_path);
  // Strings come from received messages: bytes that are not UTF-8 are replaced, never fatal.
  json_file << toJson(report).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  if (!json_file) throw ReportError(json_path.string() + ": cannot write the report");

  writePng(renderMap(record, report), dir / "map.png");
  writePng(renderWeights(record), dir / "weights.png");
}

}  // namespace beft::report
