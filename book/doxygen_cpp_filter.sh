#!/bin/sh
# Doxygen input filter for the .cpp files (Doxyfile, FILTER_PATTERNS): only a file's leading
# comment block is parsed. The .cpp files are in Doxygen's INPUT for their source listings
# (the reproduction report links the line that decides each claim), which FILTER_SOURCE_FILES
# = NO leaves unfiltered. Parsed whole, their file-local helpers (struct members named x, k,
# ok, ...) became symbols, and every such name in a quoted snippet of a chapter linked to them.
awk '!/^\/\//{exit} {print}' "$1"
