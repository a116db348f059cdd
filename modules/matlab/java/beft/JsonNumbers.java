package beft;

import java.util.regex.Pattern;

/**
 * A JSON text with every number (and every null, which on the bridge's wire
 * stands for a non-finite double) replaced by its 1-based position among
 * them, and the exact values in that order as 16 hex digits each (IEEE bits).
 * MATLAB's and Octave's jsondecode then parse only small integers, which
 * they get right; Octave's (RapidJSON without full precision) is off by an
 * ULP on about one double in ten, while Double.parseDouble is exact. A
 * text whose numbers are all such integers and that has no null is kept
 * as it is, with no hex: jsondecode reads it exactly by itself.
 */
public final class JsonNumbers {
  private static final Pattern NUMBER = Pattern.compile("-?(0|[1-9][0-9]*)(\\.[0-9]+)?([eE][-+]?[0-9]+)?");
  private static final Pattern SMALL_INTEGER = Pattern.compile("-?[0-9]{1,15}");  // below 2^53

  private final String text;
  private final String hex;

  public JsonNumbers(String json) {
    StringBuilder out = new StringBuilder(json.length());
    StringBuilder bits = new StringBuilder();
    int count = 0;
    boolean asIs = true;
    int i = 0;
    final int n = json.length();
    while (i < n) {
      char c = json.charAt(i);
      if (c == '"') {
        int end = endOfString(json, i);
        out.append(json, i, end);
        i = end;
      } else if (c == '-' || (c >= '0' && c <= '9')) {
        int end = i + 1;
        while (end < n && isNumberChar(json.charAt(end))) ++end;
        String token = json.substring(i, end);
        if (NUMBER.matcher(token).matches()) {
          out.append(++count);
          appendBits(bits, Double.parseDouble(token));
          asIs = asIs && SMALL_INTEGER.matcher(token).matches() && !token.equals("-0");
        } else {
          out.append(token);  // not JSON: left for jsondecode to refuse
        }
        i = end;
      } else if (json.startsWith("null", i)) {
        asIs = false;
        out.append(++count);
        appendBits(bits, Double.NaN);
        i += 4;
      } else {
        out.append(c);
        ++i;
      }
    }
    text = asIs ? json : out.toString();
    hex = asIs ? "" : bits.toString();
  }

  public String text() { return text; }

  public String hex() { return hex; }

  // The index just past the closing quote of the string opening at start
  // (the text's end if it is not closed). Shared with HistoryText.
  static int endOfString(String json, int start) {
    int i = start + 1;
    while (i < json.length()) {
      char c = json.charAt(i);
      if (c == '\\') i += 2;
      else if (c == '"') return i + 1;
      else ++i;
    }
    return json.length();
  }

  private static boolean isNumberChar(char c) {
    return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
  }

  private static void appendBits(StringBuilder bits, double value) {
    String digits = Long.toHexString(Double.doubleToRawLongBits(value));
    for (int pad = digits.length(); pad < 16; ++pad) bits.append('0');
    bits.append(digits);
  }
}
