// The papers' displayed formulas (papers.hpp): found in the embedded Markdown, numbered from
// the paper's own tags, placed under their section and example.
#include "vibook/printed/papers.hpp"

#include <algorithm>
#include <cctype>
#include <mutex>
#include <regex>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace vibook::printed {

namespace detail {
extern const unsigned char kPaperS[];
extern const std::size_t kPaperSSize;
extern const unsigned char kPaperV[];
extern const std::size_t kPaperVSize;
extern const unsigned char kPaperSS[];
extern const std::size_t kPaperSSSize;
}  // namespace detail

std::string_view key(Paper p) {
  switch (p) {
    case Paper::S:
      return "S";
    case Paper::V:
      return "V";
    case Paper::SS:
      return "SS";
  }
  return "S";
}

Paper paper_from_key(std::string_view k) {
  if (k == "S") return Paper::S;
  if (k == "V") return Paper::V;
  if (k == "SS") return Paper::SS;
  throw std::invalid_argument("unknown paper '" + std::string(k) + "' (S, V or SS)");
}

std::string_view file_name(Paper p) {
  switch (p) {
    case Paper::S:
      return "sharma2022-epavi.md";
    case Paper::V:
      return "vermeeren2017-modified-equations.md";
    case Paper::SS:
      return "shen-sun2025-splitting-vi.md";
  }
  return "";
}

std::string_view text(Paper p) {
  auto view = [](const unsigned char* b, std::size_t n) {
    return std::string_view(reinterpret_cast<const char*>(b), n);
  };
  switch (p) {
    case Paper::S:
      return view(detail::kPaperS, detail::kPaperSSize);
    case Paper::V:
      return view(detail::kPaperV, detail::kPaperVSize);
    case Paper::SS:
      return view(detail::kPaperSS, detail::kPaperSSSize);
  }
  return {};
}

std::string Display::id() const {
  if (inline_math)
    return "I" + std::to_string(line) + (part > 0 ? "." + std::to_string(part + 1) : "");
  return number.empty() ? "L" + std::to_string(line) : "(" + number + ")";
}

std::string Display::full_id() const { return std::string(key(paper)) + " " + id(); }

namespace {
std::string ordinal(int i) {
  const char* suffix = (i % 100 >= 11 && i % 100 <= 13) ? "th"
                       : i % 10 == 1                    ? "st"
                       : i % 10 == 2                    ? "nd"
                       : i % 10 == 3                    ? "rd"
                                                        : "th";
  return std::to_string(i) + suffix;
}
}  // namespace

// In the paper's own terms (our transcription's line numbers mean nothing to its author): which
// unnumbered display, or inline formula, after which numbered one, in which section.
std::string Display::label() const { return describe(true); }
std::string Display::place() const { return describe(false); }

namespace {

// The numbered display an unnumbered one (or an inline formula) is counted from: the last one
// before it in its own section ("" when none), its line, and how many unnumbered displays of
// that frame come before it, itself included.
struct Frame {
  std::string after;
  int after_line = 0, nth = 1;
};
Frame frame_of(const Display& me) {
  Frame f;
  for (const Display& d : displays(me.paper)) {
    if (d.line >= me.line) break;
    if (d.section != me.section) {  // counted from the start of its own section
      f = Frame{{}, d.line, 1};
    } else if (!d.number.empty()) {
      f = Frame{d.number, d.line, 1};
    } else if (!me.inline_math) {
      ++f.nth;
    }
  }
  return f;
}

// The words an inline formula follows in its sentence (up to six, back to the formula before
// it or the paragraph's start); "" when fewer than two.
std::string words_before(const Display& me) {
  const std::string_view t = text(me.paper);
  const std::size_t b = me.spans.empty() || me.spans[0].first == 0 ? 0 : me.spans[0].first - 1;
  std::size_t a = b;
  while (a > 0 && t[a - 1] != '$' && !(t[a - 1] == '\n' && a >= 2 && t[a - 2] == '\n')) --a;
  std::vector<std::string> words;
  std::string w;
  for (std::size_t i = a; i <= b; ++i) {
    const char c = i < b ? t[i] : ' ';
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!w.empty()) words.push_back(w);
      w.clear();
    } else if (c != '*' && c != '_') {
      w += c;
    }
  }
  const std::size_t from = words.size() > 6 ? words.size() - 6 : 0;
  // a sentence's punctuation before the first word kept (", where the" -> "where the")
  if (from < words.size()) words[from].erase(0, words[from].find_first_not_of(",.;:"));
  if (from < words.size() && words[from].empty()) words.erase(words.begin() + long(from));
  if (words.size() - std::min(from, words.size()) < 2) return "";
  std::string tail = from > 0 ? "… " : "";
  for (std::size_t i = from; i < words.size(); ++i) tail += (i > from ? " " : "") + words[i];
  return tail;
}

}  // namespace

std::string Display::describe(bool with_section) const {
  if (!number.empty()) return "(" + number + ")";
  const Frame f = frame_of(*this);
  const std::string& after = f.after;
  std::string s;
  if (inline_math) {
    // After its words, counted among the formulas after the same words in the same frame when
    // there are several; without words, its count in the text.
    const auto before = [this](const Display& d) {
      return d.line < line || (d.line == line && d.part < part);
    };
    if (const std::string words = words_before(*this); !words.empty()) {
      int k = 1, n = 1;
      for (const Display& d : inline_formulas(paper)) {
        if (d.line == line && d.part == part) continue;
        if (d.section != section || words_before(d) != words || frame_of(d).after != after)
          continue;
        ++n;
        if (before(d)) ++k;
      }
      s = "the formula after “" + words + "”" +
          (n > 1 ? " (the " + ordinal(k) + " of " + std::to_string(n) + ")" : "") + " in the text";
    } else {
      int nth = 1;
      for (const Display& d : inline_formulas(paper))
        if (d.line > f.after_line && before(d)) ++nth;
      s = "the " + ordinal(nth) + " formula in the text";
    }
  } else {
    s = "the " + ordinal(f.nth) + " unnumbered display";
  }
  // "3. Discrete Lagrangian Mechanics" -> "§3 Discrete Lagrangian Mechanics"
  std::string sec = section;
  if (const auto sp = sec.find(' '); sp != std::string::npos && sp > 0 && sec[sp - 1] == '.')
    sec.erase(sp - 1, 1);
  std::erase(sec, '*');  // Markdown emphasis in a heading
  if (!sec.empty() && std::isdigit(static_cast<unsigned char>(sec[0]))) sec = "§" + sec;
  if (!with_section)
    return s + (!after.empty() ? " after (" + after + ")"
                : sec.empty()  ? " of the paper"
                               : " of its section");
  if (!after.empty())
    s += " after (" + after + ")" + (sec.empty() ? "" : ", " + sec);
  else
    s += sec.empty() ? " of the paper" : " of " + sec;
  if (!context.empty()) s += " (" + context + ")";
  return s;
}

namespace {

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return std::string(s.substr(a, b - a));
}

// An equation number split into parts for the sequence test: "4.5a" -> {4, 5, 'a'},
// "21" -> {21, 0, 0}, "A3" -> {1000 + 3, 0, 0}.
struct Number {
  int major = 0, minor = 0;
  char letter = 0;
};

bool parse_number(const std::string& s, Number& n) {
  static const std::regex re(R"(^(A)?(\d+)(?:\.(\d+))?([a-z])?$)");
  std::smatch m;
  if (!std::regex_match(s, m, re)) return false;
  n.major = std::stoi(m[2]) + (m[1].matched ? 1000 : 0);
  n.minor = m[3].matched ? std::stoi(m[3]) : 0;
  n.letter = m[4].matched ? m[4].str()[0] : 0;
  return true;
}

// Does `n` continue the sequence after `last`? (1 -> 2; 4.5a -> 4.5b; 4.5c -> 4.6;
// 4.30 -> A1; 2.7 -> 3.1; 3.6b -> 3.7.)
bool continues(const Number& last, const Number& n, bool first) {
  if (first) return n.major == 1 || n.major == 2 || n.minor == 1;
  auto next_letter = [](char a, char b) { return (a == 0 && b == 'a') || (a != 0 && b == a + 1); };
  if (n.major == last.major && n.minor == last.minor) return next_letter(last.letter, n.letter);
  if (n.letter != 0 && n.letter != 'a') return false;
  if (n.major == last.major) return n.minor == last.minor + 1;
  if (n.major == last.major + 1) return n.minor <= 1;
  if (n.major >= 1000 && last.major < 1000) return n.major == 1001;
  return false;
}

struct Block {
  std::size_t begin, end;  // the body, without the $$
  int line;
};

std::vector<Display> find_displays(Paper paper) {
  const std::string_view t = text(paper);
  // Line starts, for line numbers.
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] == '\n') starts.push_back(i + 1);
  auto line_of = [&](std::size_t pos) {
    return static_cast<int>(std::upper_bound(starts.begin(), starts.end(), pos) - starts.begin());
  };
  std::vector<Block> blocks;
  for (std::size_t pos = 0;;) {
    const std::size_t a = t.find("$$", pos);
    if (a == std::string_view::npos) break;
    const std::size_t b = t.find("$$", a + 2);
    if (b == std::string_view::npos) break;
    blocks.push_back({a + 2, b, line_of(a)});
    pos = b + 2;
  }
  static const std::regex tag_end(
      R"((?:\\q?quad\s*)?\(\s*(\d+(?:\.\d+)?[a-z]?|\\text\{A\d+\})\s*\)\s*[.,]?\s*$)");
  static const std::regex tag_cmd(R"(\\tag\{([^}]*)\})");
  static const std::regex tag_line(R"(^\s*(?:<sup>)?\((\d+(?:\.\d+)?[a-z]?)\)(?:</sup>)?\s*$)");
  static const std::regex tag_text_end(R"(\((\d+(?:\.\d+)?[a-z]?)\)\s*$)");
  static const std::regex heading(R"(^#+\s*(.*)$|^(\d{1,2}\.\s+[A-Z][A-Za-z\- ]{3,70})$)");
  static const std::regex context_start(
      R"(^\s*\*{0,2}(Example|Theorem|Lemma|Proposition|Definition|Remark|Corollary)\s+([0-9A-Z]+(?:\.[0-9]+)?)\.?(?:\*{1,2}|\s+\(|\.\s)|^\s*\*(Proof)\.?\*|^(Proof)\.\s)");
  std::vector<Display> out;
  Number last;
  bool first = true;
  // Section and context as of each block: scan the lines in order.
  std::size_t line_scan = 0;
  std::string section, context;
  auto advance_to = [&](std::size_t upto) {
    while (line_scan < starts.size() && starts[line_scan] < upto) {
      const std::size_t b = starts[line_scan];
      const std::size_t e = line_scan + 1 < starts.size() ? starts[line_scan + 1] : t.size();
      std::string line(t.substr(b, e - b));
      while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
      std::smatch m;
      if (std::regex_search(line, m, heading) && line.rfind("$$", 0) != 0) {
        section = trim(m[1].matched ? m[1].str() : m[2].str());
        context.clear();
      } else if (trim(line) == "□" || trim(line) == "∎") {
        context.clear();  // the end of a proof
      } else if (std::regex_search(line, m, context_start)) {
        context = m[3].matched || m[4].matched ? "Proof" : trim(m[1].str() + " " + m[2].str());
        while (!context.empty() && context.back() == '.') context.pop_back();
      }
      ++line_scan;
    }
  };
  for (const Block& bl : blocks) {
    advance_to(bl.begin);
    const std::string body(t.substr(bl.begin, bl.end - bl.begin));
    const std::string lead = trim(body);
    // A continuation of the display before: starts with a relation or a sign, the display
    // before has no number, and only blank space lies between them.
    bool continuation = false;
    if (!out.empty() && out.back().number.empty()) {
      const std::size_t prev_end = out.back().spans.back().second + 2;
      const std::string between(t.substr(prev_end, bl.begin - 2 - prev_end));
      const bool blank = trim(between).empty();
      static const char* const lead_ops[] = {"=",       "+",        "-",     "\\pm",
                                             ">",       "<",        "\\leq", "\\geq",
                                             "\\simeq", "\\approx", "\\le ", "\\ge "};
      bool op = false;
      for (const char* o : lead_ops) op = op || lead.rfind(o, 0) == 0;
      continuation = blank && op;
    }
    std::string number;
    std::vector<std::pair<std::size_t, std::size_t>> inline_parts;
    std::smatch m;
    if (std::regex_search(body, m, tag_cmd)) {
      number = m[1].str();
    } else if (std::regex_search(body, m, tag_end)) {
      number = m[1].str();
      static const std::regex text_a(R"(\\text\{(A\d+)\})");
      std::smatch ma;
      if (std::regex_search(number, ma, text_a)) number = ma[1].str();
    } else {
      // The line right after the block: "(22)", "<sup>(20)</sup>", or text ending in "(5)".
      std::size_t after = bl.end + 2;
      std::size_t eol = t.find('\n', after);
      if (eol == std::string_view::npos) eol = t.size();
      std::size_t rest_begin = after;
      std::string rest = trim(t.substr(after, eol - after));
      for (int skipped = 0; rest.empty() && eol < t.size() && skipped < 3; ++skipped) {
        const std::size_t e2 = std::min(t.find('\n', eol + 1), t.size());
        rest_begin = eol + 1;
        rest = trim(t.substr(eol + 1, e2 - eol - 1));
        eol = e2;
      }
      if (rest.rfind("$$", 0) == 0) rest.clear();  // the next display
      if (std::regex_search(rest, m, tag_line)) {
        number = m[1].str();
      } else if (std::regex_search(rest, m, tag_text_end)) {
        number = m[1].str();
        // The text line that carries the number may hold the rest of the numbered formula
        // as inline math ("… and $p_{j+1} = D_2 L(…).$ (5)"): those parts belong to it.
        for (std::size_t k = rest_begin; k < eol; ++k) {
          if (t[k] != '$' || (k + 1 < eol && t[k + 1] == '$')) continue;
          const std::size_t close = t.find('$', k + 1);
          if (close == std::string_view::npos || close >= eol) break;
          inline_parts.emplace_back(k + 1, close);
          k = close;
        }
      }
    }
    Number n;
    if (!number.empty() && !(parse_number(number, n) && continues(last, n, first))) number.clear();
    if (!number.empty()) {
      last = n;
      first = false;
    } else {
      inline_parts.clear();
    }
    if (continuation && !out.empty()) {
      Display& d = out.back();
      d.latex += " " + lead;
      d.spans.emplace_back(bl.begin, bl.end);
      for (const auto& [b, e] : inline_parts) {
        d.latex += " \\quad " + trim(t.substr(b, e - b));
        d.spans.emplace_back(b, e);
      }
      d.number = number;
      continue;
    }
    Display d;
    d.paper = paper;
    d.index = static_cast<int>(out.size());
    d.line = bl.line;
    d.number = number;
    d.section = section;
    d.context = context;
    d.latex = lead;
    d.spans.emplace_back(bl.begin, bl.end);
    for (const auto& [b, e] : inline_parts) {
      d.latex += " \\quad " + trim(t.substr(b, e - b));
      d.spans.emplace_back(b, e);
    }
    out.push_back(std::move(d));
  }
  return out;
}

// Inline formulas: every $…$ outside the $$ blocks, on one line, with the section and context
// of the text it stands in.
std::vector<Display> find_inline(Paper paper) {
  const std::string_view t = text(paper);
  static const std::regex heading(R"(^#+\s*(.*)$|^(\d{1,2}\.\s+[A-Z][A-Za-z\- ]{3,70})$)");
  static const std::regex context_start(
      R"(^\s*\*{0,2}(Example|Theorem|Lemma|Proposition|Definition|Remark|Corollary)\s+([0-9A-Z]+(?:\.[0-9]+)?)\.?(?:\*{1,2}|\s+\(|\.\s)|^\s*\*(Proof)\.?\*|^(Proof)\.\s)");
  std::vector<Display> out;
  std::string section, context;
  bool in_block = false;
  int line = 0;
  for (std::size_t b = 0; b < t.size();) {
    std::size_t e = t.find('\n', b);
    if (e == std::string_view::npos) e = t.size();
    ++line;
    const std::string_view l = t.substr(b, e - b);
    const std::string ls(l);
    std::smatch m;
    if (!in_block && std::regex_search(ls, m, heading)) {
      section = trim(m[1].matched ? m[1].str() : m[2].str());
      context.clear();
    } else if (!in_block && (trim(ls) == "□" || trim(ls) == "∎")) {
      context.clear();
    } else if (!in_block && std::regex_search(ls, m, context_start)) {
      context = m[3].matched || m[4].matched ? "Proof" : trim(m[1].str() + " " + m[2].str());
      while (!context.empty() && context.back() == '.') context.pop_back();
    }
    int k = 0;
    for (std::size_t i = 0; i < l.size(); ++i) {
      if (l[i] != '$') continue;
      if (i + 1 < l.size() && l[i + 1] == '$') {
        in_block = !in_block;
        ++i;
        continue;
      }
      if (in_block) continue;
      const std::size_t close = l.find('$', i + 1);
      if (close == std::string_view::npos) break;
      if (close + 1 < l.size() && l[close + 1] == '$') break;
      Display d;
      d.paper = paper;
      d.index = -1;
      d.line = line;
      d.inline_math = true;
      d.part = k++;
      d.section = section;
      d.context = context;
      d.latex = trim(l.substr(i + 1, close - i - 1));
      d.spans.emplace_back(b + i + 1, b + close);
      out.push_back(std::move(d));
      i = close;
    }
    b = e + 1;
  }
  return out;
}

}  // namespace

const std::vector<Display>& inline_formulas(Paper p) {
  static std::once_flag once;
  static std::vector<Display> all[3];
  std::call_once(once, [] {
    for (Paper q : {Paper::S, Paper::V, Paper::SS}) all[static_cast<int>(q)] = find_inline(q);
  });
  return all[static_cast<int>(p)];
}

const std::vector<Display>& displays(Paper p) {
  static std::once_flag once;
  static std::vector<Display> all[3];
  std::call_once(once, [] {
    for (Paper q : {Paper::S, Paper::V, Paper::SS}) all[static_cast<int>(q)] = find_displays(q);
  });
  return all[static_cast<int>(p)];
}

const Display& display(Paper p, std::string_view id) {
  std::string want(id);
  if (!want.empty() && want.front() != '(' && want.front() != 'L') want = "(" + want + ")";
  for (const auto& d : displays(p))
    if (d.id() == want) return d;
  for (const auto& d : inline_formulas(p))
    if (d.id() == want) return d;
  throw std::invalid_argument("paper " + std::string(key(p)) + " has no display " +
                              std::string(id));
}

bool quotes(const Display& d, std::string_view quote) {
  const std::string_view t = text(d.paper);
  for (const auto& [b, e] : d.spans) {
    const std::string_view block = t.substr(b, e - b);
    if (block.find(quote) != std::string_view::npos) return true;
  }
  return false;
}

const Display& display_quoting(Paper p, std::string_view quote) {
  if (quote.empty()) throw std::invalid_argument("an empty quote names no display");
  const Display* found = nullptr;
  std::string all;
  for (const auto& d : displays(p)) {
    if (!quotes(d, quote)) continue;
    all += (all.empty() ? "" : ", ") + d.id();
    if (found) {
      for (const auto& e : displays(p))
        if (&e != found && &e != &d && quotes(e, quote)) all += ", " + e.id();
      throw std::invalid_argument("the quote occurs in more than one display of paper " +
                                  std::string(key(p)) + " (" + all + "): quote more of it");
    }
    found = &d;
  }
  if (!found) {
    // not in a display: an inline formula of the text, if exactly one holds it
    for (const auto& d : inline_formulas(p)) {
      if (!quotes(d, quote)) continue;
      if (found)
        throw std::invalid_argument("the quote occurs in more than one inline formula of paper " +
                                    std::string(key(p)) + " (" + found->id() + ", " + d.id() +
                                    "): quote more of it");
      found = &d;
    }
  }
  if (!found)
    throw std::invalid_argument(
        "the quote does not occur in any display or inline formula of paper " +
        std::string(key(p)) + " (" + std::string(file_name(p)) +
        "): " + std::string(quote.substr(0, 120)));
  return *found;
}

DisplayListing list_displays(const std::vector<Paper>& papers, bool with_inline) {
  const std::vector<Paper> which =
      papers.empty() ? std::vector<Paper>{Paper::S, Paper::V, Paper::SS} : papers;
  nlohmann::json out = nlohmann::json::array();
  std::string table;
  for (Paper p : which) {
    std::vector<const Display*> all;
    for (const auto& d : displays(p)) all.push_back(&d);
    if (with_inline)
      for (const auto& d : inline_formulas(p)) all.push_back(&d);
    for (const auto* d : all) {
      out.push_back({{"paper", std::string(key(p))},
                     {"id", d->id()},
                     {"label", d->label()},
                     {"place", d->place()},
                     {"number", d->number},
                     {"line", d->line},
                     {"section", d->section},
                     {"context", d->context},
                     {"inline", d->inline_math},
                     {"latex", d->latex}});
      std::string head = d->latex.substr(0, 70);
      for (auto& ch : head)
        if (ch == '\n') ch = ' ';
      table += fmt::format("{:<3} {:<8} {:<40.40} {}{}\n", key(p), d->id(),
                           d->section + (d->context.empty() ? "" : " / " + d->context), head,
                           d->latex.size() > 70 ? "…" : "");
    }
  }
  return {out.dump(2) + "\n", table};
}

}  // namespace vibook::printed
