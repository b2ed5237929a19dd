/*
 * base/number.c -- the command line's number syntax (number.h).
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

int number_parse(const char *text, int integer, double *value)
{
    *value = 0;
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
    if (*s != '\0')
        return 0;
    *value = strtod(text, NULL);
    return isfinite(*value);
}
