package dev.trade.bench;

/** A minimal streaming JSON writer for the results file (numbers, strings, objects, arrays). */
final class Json {
  private final StringBuilder sb = new StringBuilder();
  private boolean needComma;

  Json begin() {
    comma();
    sb.append('{');
    needComma = false;
    return this;
  }

  Json end() {
    sb.append('}');
    needComma = true;
    return this;
  }

  Json beginArray() {
    comma();
    sb.append('[');
    needComma = false;
    return this;
  }

  Json endArray() {
    sb.append(']');
    needComma = true;
    return this;
  }

  /** Starts a member whose value follows (an object or array). */
  Json key(String name) {
    comma();
    string(name);
    sb.append(':');
    needComma = false;
    return this;
  }

  Json field(String name, Object value) {
    key(name);
    value(value);
    return this;
  }

  Json value(Object v) {
    comma();
    if (v == null) {
      sb.append("null");
    } else if (v instanceof Double d && (d.isNaN() || d.isInfinite())) {
      sb.append("null");
    } else if (v instanceof Number || v instanceof Boolean) {
      sb.append(v);
    } else {
      string(v.toString());
    }
    needComma = true;
    return this;
  }

  /** Inserts already-encoded JSON as a value. */
  Json raw(String json) {
    comma();
    sb.append(json);
    needComma = true;
    return this;
  }

  private void comma() {
    if (needComma) {
      sb.append(',');
    }
  }

  private void string(String s) {
    sb.append('"');
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      if (c == '"' || c == '\\') {
        sb.append('\\').append(c);
      } else if (c < 0x20) {
        sb.append(String.format("\\u%04x", (int) c));
      } else {
        sb.append(c);
      }
    }
    sb.append('"');
  }

  @Override
  public String toString() {
    return sb.toString();
  }
}
