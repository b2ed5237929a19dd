/*
 * tests/test_docs.c -- the documentation against the product: tests/docs.sh checks that
 * every file the documents name exists, that every option their command lines show is one
 * photon takes, and runs the README's commands as shown.
 */
#include <stdio.h>

#include "check.h"
#include "tests.h"

/* truth: the files in the tree, photon's own --help, and the exit status of each README
 *   command run as a user would (with --quality preview appended to renders).
 * catches: a document naming a file that was moved or never committed, an option renamed
 *   or removed under the README's feet, a command whose output directory or input is
 *   missing in a fresh clone. */
static void test_documented_commands_work(struct check *t)
{
    char command[1024];
    snprintf(command, sizeof command, "sh tests/docs.sh %s", photon_binary());
    CHECK(t, run_command(command) == 0);
}

void test_docs(struct check *t)
{
    RUN_TEST(t, test_documented_commands_work);
}
