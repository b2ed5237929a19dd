/*
 * base/option_equals.c -- --NAME=VALUE as --NAME VALUE (option_equals.h).
 */
#include "option_equals.h"

#include <assert.h>
#include <string.h>

#include "alloc.h"

/* The option of table spelt name[0 .. length - 1], or NULL. */
static const struct option_arity *find_option(const struct option_arity *table,
                                              const char *name, size_t length)
{
    for (; table->name != NULL; table++)
        if (strlen(table->name) == length && strncmp(table->name, name, length) == 0)
            return table;
    return NULL;
}

/* "no value", "two values", ... for a message: the most any option takes is six
 * (probe's --line). */
static const char *values_in_words(int values)
{
    static const char *const words[] = {"no value",    "one value",  "two values",
                                        "three values", "four values", "five values",
                                        "six values"};
    assert(values >= 0 && values < (int)(sizeof words / sizeof words[0]));
    return words[values];
}

int split_equals(const char *command, int argc, char **argv,
                 const struct option_arity *table, char ***split, int *split_argc,
                 struct error *err)
{
    *split = xmalloc(2 * (size_t)argc + 1, sizeof **split, "command line");
    int words = 0;
    for (int i = 0; i < argc; i++) {
        const char *equals = strchr(argv[i], '=');
        const struct option_arity *option =
            i > 0 && strncmp(argv[i], "--", 2) == 0 && equals != NULL
                ? find_option(table, argv[i], (size_t)(equals - argv[i]))
                : NULL;
        if (option == NULL) {
            (*split)[words++] = argv[i];
            continue;
        }
        if (option->values != 1)
            return error_set(err, "", 0, "%s%s%s: %s takes %s, not '=' and a value", command,
                             command[0] != '\0' ? ": " : "", argv[i], option->name,
                             values_in_words(option->values));
        (*split)[words++] = (char *)option->name; /* only read */
        (*split)[words++] = (char *)equals + 1;
    }
    (*split)[words] = NULL;
    *split_argc = words;
    return 0;
}
