/*
 * The application side of the SOES firmware the esi-sim tests run (soes_firmware.h): the object
 * storage the generated utypes.h declares, SOES's application callbacks, and the functions the
 * host program calls. The host moves values in and out of the dictionary itself (esi_soes_get,
 * esi_soes_set), so the callbacks have nothing to do.
 */
#include <string.h>

#include "ecat_slv.h"
#include "esc_coe.h"
#include "soes_firmware.h"
#include "utypes.h"

_Objects Obj;

void cb_get_inputs (void) {}
void cb_set_outputs (void) {}

void esi_soes_init (void)
{
   /* Polling, no interrupts. The software watchdog (SOES counts main-loop iterations without
    * new outputs) is set far out of reach: the host polls after every frame, not on a clock,
    * and the tests judge the process data, not the watchdog. */
   static esc_cfg_t config;
   memset (&config, 0, sizeof config);
   config.watchdog_cnt = 1000000;
   ecat_slv_init (&config);
}

void esi_soes_run (void) { ecat_slv (); }

uint8_t esi_soes_al_status (void) { return (uint8_t)ESCvar.ALstatus; }

static const _objd *find (uint16_t index, uint8_t subindex)
{
   const int32_t object = SDO_findobject (index);
   if (object < 0) return NULL;
   const int16_t entry = SDO_findsubindex (object, subindex);
   if (entry < 0) return NULL;
   const _objd *description = SDOobjects[object].objdesc + entry;
   if (description->data == NULL || description->bitlength == 0 || description->bitlength > 64) return NULL;
   return description;
}

/* Values are stored as SOES's COE_getValue reads them: in the smallest of 8, 16, 32, 64 bits
 * that holds the object. */
int esi_soes_get (uint16_t index, uint8_t subindex, uint64_t *value, uint16_t *bit_length)
{
   const _objd *o = find (index, subindex);
   if (o == NULL) return -1;
   *bit_length = o->bitlength;
   if (o->bitlength <= 8) *value = *(const uint8_t *)o->data;
   else if (o->bitlength <= 16) *value = *(const uint16_t *)o->data;
   else if (o->bitlength <= 32) *value = *(const uint32_t *)o->data;
   else *value = *(const uint64_t *)o->data;
   return 0;
}

int esi_soes_set (uint16_t index, uint8_t subindex, uint64_t value)
{
   const _objd *o = find (index, subindex);
   if (o == NULL) return -1;
   /* Only the object's own bits: SOES packs the low bitlength bits into the process data. */
   if (o->bitlength < 64) value &= (UINT64_C (1) << o->bitlength) - 1u;
   if (o->bitlength <= 8) *(uint8_t *)o->data = (uint8_t)value;
   else if (o->bitlength <= 16) *(uint16_t *)o->data = (uint16_t)value;
   else if (o->bitlength <= 32) *(uint32_t *)o->data = (uint32_t)value;
   else *(uint64_t *)o->data = value;
   return 0;
}
