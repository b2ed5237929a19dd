/*
 * base/number.c -- the one number syntax (number.h).
 */
#include "number.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>

/* The count of decimal digits at s. */
static int digits(const char *s)
{
    int n = 0;
    while (isdigit((unsigned char)s[n]))
        n++;
    return n;
}

/* Whether the digits before the exponent include one that is not 0: strtod's 0 from such
 * text is an underflow, not the number written. */
static int mantissa_is_nonzero(const char *s)
{
    for (; *s != '\0' && *s != 'e' && *s != 'E'; s++)
        if (*s >= '1' && *s <= '9')
            return 1;
    return 0;
}

int number_in_syntax(const char *text, int integer)
{
    if (text == NULL)
        return 0;
    const char *s = text;
    if (*s == '-' || (!integer && *s == '+'))
        s++;
    int n = digits(s);
    s += n;
    if (!integer && *s == '.') {
        int fraction = digits(s + 1);
        n += fraction;
        s += 1 + fraction;
    }
    if (n == 0)
        return 0;
    if (!integer && (*s == 'e' || *s == 'E')) {
        s++;
        if (*s == '-' || *s == '+')
            s++;
        int exponent = digits(s);
        if (exponent == 0)
            return 0;
        s += exponent;
    }
    return *s == '\0';
}

enum number_verdict number_read(const char *text, int integer, double *value)
{
    *value = 0;
    char *end = NULL;
    double v = text != NULL ? strtod(text, &end) : 0;
    if (!number_in_syntax(text, integer))
        /* strtod's "inf" and "nan" are named for what they are */
        return end != text && *end == '\0' && !isfinite(v) ? NUMBER_INFINITE
                                                           : NUMBER_UNWRITTEN;
    if (!isfinite(v))
        return NUMBER_INFINITE;
    if (v == 0 && mantissa_is_nonzero(text))
        return NUMBER_UNDERFLOW;
    *value = v;
    return NUMBER_OK;
}

const char *number_problem(enum number_verdict verdict, int integer)
{
    switch (verdict) {
    case NUMBER_OK:
        break;
    case NUMBER_UNWRITTEN:
        return integer ? "is not a whole number" : "is not a number";
    case NUMBER_INFINITE:
        return "is not finite";
    case NUMBER_UNDERFLOW:
        return "is too small for a double (it would be read as 0)";
    }
    return "is a number";
}

int number_parse(const char *text, int integer, double *value)
{
    return number_read(text, integer, value) == NUMBER_OK;
}
