#include "planners/movingai.hpp"

#include <fstream>
#include <sstream>

namespace beft::planners {
namespace {

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw MapFormatError(path + ":" + std::to_string(line) + ": " + what);
}

bool readLine(std::istream& in, std::string& line, int& number) {
  if (!std::getline(in, line)) return false;
  ++number;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

int parseHeaderValue(const std::string& path, int number, const std::string& line, const std::string& key) {
  std::istringstream fields(line);
  std::string word;
  long value = 0;
  if (!(fields >> word) || word != key || !(fields >> value)) {
    fail(path, number, "expected '" + key + " N', found '" + line + "'");
  }
  if (value <= 0 || value > 100000) fail(path, number, key + " " + std::to_string(value) + " is out of range");
  return static_cast<int>(value);
}

}  // namespace

GridMap loadMovingAiMap(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw MapFormatError(path + ": cannot open the map file");
  std::string line;
  int number = 0;
  if (!readLine(in, line, number) || line.rfind("type", 0) != 0) {
    fail(path, number == 0 ? 1 : number, "expected 'type octile' (not a MovingAI map)");
  }
  if (!readLine(in, line, number)) fail(path, number, "missing 'height'");
  const int height = parseHeaderValue(path, number, line, "height");
  if (!readLine(in, line, number)) fail(path, number, "missing 'width'");
  const int width = parseHeaderValue(path, number, line, "width");
  if (!readLine(in, line, number) || line != "map") fail(path, number, "expected 'map'");
  GridMap grid(width, height);
  for (int y = 0; y < height; ++y) {
    if (!readLine(in, line, number)) {
      fail(path, number + 1, "the map ends after " + std::to_string(y) + " of the " + std::to_string(height) +
                                 " rows the header announces");
    }
    if (static_cast<int>(line.size()) != width) {
      fail(path, number, "row has " + std::to_string(line.size()) + " cells, the header says " + std::to_string(width));
    }
    for (int x = 0; x < width; ++x) {
      switch (line[x]) {
        case '.': case 'G': case 'S': break;
        case '@': case 'O': case 'T': case 'W': grid.setBlocked(x, y); break;
        default: fail(path, number, std::string("unknown cell character '") + line[x] + "' in column " + std::to_string(x));
      }
    }
  }
  return grid;
}

std::vector<MovingAiQuery> loadMovingAiScenario(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw MapFormatError(path + ": cannot open the scenario file");
  std::string line;
  int number = 0;
  if (!readLine(in, line, number) || line.rfind("version", 0) != 0) {
    fail(path, number == 0 ? 1 : number, "expected 'version 1' (not a MovingAI scenario file)");
  }
  std::vector<MovingAiQuery> queries;
  while (readLine(in, line, number)) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    std::istringstream fields(line);
    MovingAiQuery q;
    q.line = number;
    if (!(fields >> q.bucket >> q.map >> q.map_width >> q.map_height >> q.start_x >> q.start_y >> q.goal_x >>
          q.goal_y >> q.optimal_length)) {
      fail(path, number, "expected 9 fields: bucket map width height sx sy gx gy optimal_length");
    }
    const auto inside = [&q](int x, int y) { return x >= 0 && y >= 0 && x < q.map_width && y < q.map_height; };
    if (!inside(q.start_x, q.start_y) || !inside(q.goal_x, q.goal_y)) {
      fail(path, number, "start or goal lies outside the " + std::to_string(q.map_width) + " x " +
                             std::to_string(q.map_height) + " map");
    }
    if (q.optimal_length < 0) fail(path, number, "negative optimal length");
    queries.push_back(q);
  }
  return queries;
}

}  // namespace beft::planners
