/*
 * base/number.h -- the one syntax of a number, wherever photon reads one: the command
 * line, scene files, NFF and OBJ files, PFM headers, crop records and CSV files.
 *
 * A whole number is an optional '-' and decimal digits ("16", "-3"); a reader whose range
 * has no negative numbers refuses "-3" by its range. A real number is an optional sign,
 * digits with at most one '.', at least one digit, and an optional exponent 'e' or 'E',
 * sign, digits ("0.7", "1e6", ".5", "-2.5E-3", "1.0e-05"). Nothing else: no white space
 * before or after, no '+' before a whole number, no hexadecimal ("0x10", "0x1p1"), no
 * "inf" or "nan" (strtod's own syntax takes all of those, so " 5" passed where "5 " did
 * not). "1e3" and "2.0" are real numbers, not whole ones: sizes and counts are written in
 * digits. A value a double cannot hold is refused, whether too large ("1e999") or too
 * small, rounded to 0 from digits that are not all 0 ("1e-400").
 */
#ifndef PHOTON_NUMBER_H
#define PHOTON_NUMBER_H

/* What number_read() found. */
enum number_verdict {
    NUMBER_OK,       /* a number in the syntax, *value its value */
    NUMBER_UNWRITTEN, /* not in the syntax ("0x10", "2.0" for a whole number, " 5") */
    NUMBER_INFINITE, /* "inf", "nan", or too large for a double ("1e999") */
    NUMBER_UNDERFLOW /* too small for a double: rounds to 0 from digits not all 0 ("1e-400") */
};

/* Reads text as a number in the syntax above (whole only when integer != 0): *value is
 * its value (strtod's) when NUMBER_OK, 0 otherwise. */
enum number_verdict number_read(const char *text, int integer, double *value);

/* A verdict's reason in words, to follow the quoted text in a message ("is not finite");
 * "is not a number" or "is not a whole number" for NUMBER_UNWRITTEN. */
const char *number_problem(enum number_verdict verdict, int integer);

/* Whether text is written in the syntax above, whatever its value: 1 or 0 (a reader that
 * looks ahead for an optional number, then lets number_read() say what is wrong). */
int number_in_syntax(const char *text, int integer);

/* Whether number_read() finds NUMBER_OK: 1 or 0. */
int number_parse(const char *text, int integer, double *value);

#endif
