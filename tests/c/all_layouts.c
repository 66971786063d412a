/* Every shipped description's C layout, and the PROFIdrive fixture's, in one
 * translation unit, as firmware that speaks to several cards includes them;
 * one twice, as a header may be reached by two paths. tests/c_header.rs compiles it as C99, C11 and C++17
 * with every warning an error, freestanding: the headers need nothing beyond
 * <stdbool.h>, <stddef.h> and <stdint.h>. */
#include "md810dp_layout.h"
#include "mv810_pnet02_layout.h"
#include "9kdp1_layout.h"
#include "md810_gateway_layout.h"
#include "profidrive_layout.h"
#include "md810dp_layout.h"

/* One name of each layout, so the unit uses all five. */
uint16_t all_layouts_ident_numbers(void);

uint16_t all_layouts_ident_numbers(void)
{
    return (uint16_t)(MD810DP_PROFIBUS_IDENT_NUMBER ^ MV810_PNET02_PROFINET_DEVICE_ID ^
                      GSDC_9KDP1_PROFIBUS_IDENT_NUMBER ^ MD810_GATEWAY_PROFIBUS_IDENT_NUMBER ^
                      PROFIDRIVE_PROFIBUS_IDENT_NUMBER);
}
