/*
 * tests/close_to.c -- the relative tolerance behind close_to.h.
 */
#include "close_to.h"

#include <math.h>

int close_to(double a, double b, double tolerance)
{
    return fabs(a - b) <= tolerance * fabs(b);
}
