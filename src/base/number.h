/*
 * base/number.h -- the one syntax of a number given on the command line.
 *
 * A whole number is an optional '-' and decimal digits ("16", "-3"); a real number is an
 * optional sign, digits with at most one '.', at least one digit, and an optional
 * exponent 'e' or 'E', sign, digits ("0.7", "1e6", ".5", "-2.5E-3"). Nothing else: no
 * white space before or after, no hexadecimal, no "inf" or "nan" (strtod's own syntax
 * takes all of those, so " 5" passed where "5 " did not). "1e3" is a real number, not a
 * whole one: sizes and counts are written in digits.
 */
#ifndef PHOTON_NUMBER_H
#define PHOTON_NUMBER_H

/* Whether text is a number in the syntax above (whole only when integer != 0); *value
 * is its value (strtod's), finite when it is one. */
int number_parse(const char *text, int integer, double *value);

#endif
