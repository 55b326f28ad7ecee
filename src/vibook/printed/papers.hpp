/// \file papers.hpp
/// \brief The three papers as vibook reads them: their Markdown text (papers/*.md, embedded at
/// build time) and the list of their displayed formulas, each with its equation number (when it
/// has one), its place in the paper and its LaTeX.
///
/// A *display* is one `$$…$$` block of the paper file, or a run of such blocks that the paper
/// breaks over several lines (a block that starts with `=`, `+`, `−`, `±` or a relation and
/// carries no number of its own continues the one before it). Its number is read from the
/// paper's own text: a tag at the end of the block (`\\quad (39)`, `\\tag{21}`, `(\\text{A1})`),
/// or a line `(22)` or `<sup>(20)</sup>` right after it, or a text line right after it that
/// ends with the number; a number is accepted only where it continues the paper's sequence.
///
/// Chapter: \ref formulas.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vibook::printed {

/// S: Sharma et al. 2022; V: Vermeeren 2017; SS: Shen & Sun 2025.
enum class Paper { S, V, SS };

/// "S", "V" or "SS".
std::string_view key(Paper p);
/// "S", "V" or "SS" to the paper; std::invalid_argument otherwise.
Paper paper_from_key(std::string_view key);
/// The file name under papers/ ("sharma2022-epavi.md", …).
std::string_view file_name(Paper p);
/// The paper's whole Markdown text.
std::string_view text(Paper p);

struct Display {
  Paper paper = Paper::S;
  int index = 0;        ///< position among the paper's displays, from 0
  int line = 0;         ///< line of the paper file where it starts (from 1)
  std::string number;   ///< "39", "4.21", "A1"; empty when unnumbered
  std::string section;  ///< the heading it stands under ("5.1.1 Störmer–Verlet")
  std::string context;  ///< the example, theorem or proof it belongs to ("Example 4"), if any
  std::string latex;    ///< the display's LaTeX (blocks of a broken display joined by a space)
  std::vector<std::pair<std::size_t, std::size_t>> spans;  ///< byte ranges of its blocks
  bool inline_math = false;  ///< an inline formula $…$ of the text, not a display
  int part = 0;              ///< inline: which formula of its line, from 0

  /// "(39)" for a numbered display, "L288" (its first line) otherwise, "I307" (or "I307.2",
  /// the second on its line) for an inline formula: stable, unique in its paper.
  std::string id() const;
  /// "S (39)", "V L288": unique across the papers.
  std::string full_id() const;
  /// For a reader, in the paper's terms: "(39)", or "the 2nd unnumbered display after (39),
  /// §5.1 Numerical examples (Example 2)", "the 1st formula in the text after (4.23), …".
  std::string label() const;
  /// The label without the section and context (a table that shows them in a column of their
  /// own): "(39)", "the 2nd unnumbered display after (39)", "the 1st … of its section".
  std::string place() const;

 private:
  std::string describe(bool with_section) const;
};

/// Every display of the paper, in order.
const std::vector<Display>& displays(Paper p);

/// Every inline formula `$…$` of the paper's text, in order (compared where a check needs a
/// formula the paper states in a sentence: a Lagrangian, N[x] in a proof).
const std::vector<Display>& inline_formulas(Paper p);

/// The display (or inline formula) with this id ("(39)", "39", "L288"); std::invalid_argument
/// naming the paper and the id when there is none.
const Display& display(Paper p, std::string_view id);

/// The display whose text contains `quote` verbatim (the quote's bytes must lie inside one
/// block of the display); when no display does, the one inline formula that does.
/// std::invalid_argument when `quote` occurs in no display of the paper, or in more than one (then
/// it names them): a quote must be long enough to say which display it is from.
const Display& display_quoting(Paper p, std::string_view quote);

/// `vibook displays`: the displays (with `with_inline` also the inline formulas) of `papers`
/// (all three when empty), as JSON text (an array of paper, id, label, place, number, line,
/// section, context, inline, latex; indented by 2) and as a table of one line each.
struct DisplayListing {
  std::string json, table;
};
DisplayListing list_displays(const std::vector<Paper>& papers, bool with_inline);

/// True if `quote` occurs verbatim in display `d` (inside one of its blocks).
bool quotes(const Display& d, std::string_view quote);

}  // namespace vibook::printed
