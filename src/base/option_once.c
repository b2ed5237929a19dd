/*
 * base/option_once.c -- refusing an option given twice (option_once.h).
 */
#include "option_once.h"

#include <stdio.h>
#include <string.h>

#define TYPED_MAX 160 /* an option and its values as typed, in a message */

/* argv[i] and the n_values words after it, as typed, into text[TYPED_MAX]; cut where it
 * is full. */
static void as_typed(int argc, char **argv, int i, int n_values, char text[TYPED_MAX])
{
    size_t n = (size_t)snprintf(text, TYPED_MAX, "%s", argv[i]);
    for (int k = 1; k <= n_values && i + k < argc && n < TYPED_MAX; k++)
        n += (size_t)snprintf(text + n, TYPED_MAX - n, " %s", argv[i + k]);
}

int option_given_again(const char *command, int argc, char **argv, int earlier, int i,
                       int n_values, struct error *err)
{
    char now[TYPED_MAX], before[TYPED_MAX];
    as_typed(argc, argv, i, n_values, now);
    as_typed(argc, argv, earlier, n_values, before);
    return error_set(err, "", 0, "%s%s%s: given after %s; give the option once", command,
                     command[0] != '\0' ? ": " : "", now, before);
}

int option_once(struct option_once *once, const char *command, int argc, char **argv, int i,
                int n_values, struct error *err)
{
    for (int k = 0; k < once->n; k++) {
        if (strcmp(argv[once->at[k]], argv[i]) == 0)
            return option_given_again(command, argc, argv, once->at[k], i, n_values, err);
    }
    if (once->n < OPTION_ONCE_MAX)
        once->at[once->n++] = i;
    return 0;
}
