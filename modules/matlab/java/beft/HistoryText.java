package beft;

/**
 * Whether a server text message is one event of the run's history for a
 * resuming expert: a JSON object whose top-level member "op" is the string
 * "beftHistory" (the messages' own members, deeper, are not looked at).
 */
final class HistoryText {
  private HistoryText() {}

  static boolean isHistory(String json) {
    int i = skipSpace(json, 0);
    if (i >= json.length() || json.charAt(i) != '{') return false;
    int depth = 0;
    boolean expectKey = true;
    while (i < json.length()) {
      char c = json.charAt(i);
      if (c == '"') {
        int end = JsonNumbers.endOfString(json, i);
        if (depth == 1 && expectKey) {
          String key = json.substring(i + 1, end - 1);
          int value = skipSpace(json, end);
          if (value < json.length() && json.charAt(value) == ':') value = skipSpace(json, value + 1);
          if (key.equals("op")) return json.startsWith("\"beftHistory\"", value);
          expectKey = false;
          i = value;
          continue;
        }
        i = end;
        continue;
      }
      if (c == '{' || c == '[') ++depth;
      else if (c == '}' || c == ']') --depth;
      else if (c == ',' && depth == 1) expectKey = true;
      if (c == '{' && depth == 1) expectKey = true;
      ++i;
    }
    return false;
  }

  private static int skipSpace(String json, int i) {
    while (i < json.length() && Character.isWhitespace(json.charAt(i))) ++i;
    return i;
  }
}
