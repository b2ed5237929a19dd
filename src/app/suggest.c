/*
 * app/suggest.c -- the near miss a mistyped word was meant to be (suggest.h).
 */
#include "suggest.h"

#include <stdio.h>
#include <string.h>

#define SUGGEST_LONGEST 64 /* words longer than this are suggested nothing */

/* The optimal string alignment distance of a and b (suggest.h), both at most
 * SUGGEST_LONGEST characters: d[i][j] is the distance of a's first i characters and b's
 * first j, filled row by row. */
static int distance(const char *a, const char *b)
{
    size_t m = strlen(a), n = strlen(b);
    int d[SUGGEST_LONGEST + 1][SUGGEST_LONGEST + 1];
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            if (i == 0 || j == 0) {
                d[i][j] = (int)(i + j);
                continue;
            }
            int best = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            if (d[i - 1][j] + 1 < best)
                best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
                d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1;
            d[i][j] = best;
        }
    return d[m][n];
}

const char *nearest_name(const char *word, const char *(*name_at)(size_t i), size_t n)
{
    const char *nearest = NULL;
    int nearest_distance = 0;
    if (word == NULL || strlen(word) > SUGGEST_LONGEST)
        return NULL;
    for (size_t i = 0; i < n; i++) {
        const char *name = name_at(i);
        if (strlen(name) > SUGGEST_LONGEST)
            continue;
        size_t length = strlen(name);
        int d = distance(word, name), limit = length <= 2 ? 0 : length <= 4 ? 1 : 2;
        if (d <= limit && (nearest == NULL || d < nearest_distance)) {
            nearest = name;
            nearest_distance = d;
        }
    }
    return nearest;
}

void did_you_mean(const char *word, const char *(*name_at)(size_t i), size_t n, char *text,
                  size_t size)
{
    const char *name = nearest_name(word, name_at, n);
    if (name != NULL)
        snprintf(text, size, " (did you mean '%s'?)", name);
    else if (size > 0)
        text[0] = '\0';
}
