/* bs_board_host.c - the board hooks of tests/embedded/scene_run.c on the
 * host, where nothing is counted: the host build of the firmware exists to
 * compare its output with the targets'. */
#include "bs_board.h"

void bs_board_mark(void)
{
}

void bs_board_stack_paint(void)
{
}

unsigned bs_board_stack_used(void)
{
    return 0;
}

unsigned bs_board_stack_painted(void)
{
    return 0;
}
