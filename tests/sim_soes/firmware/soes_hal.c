/*
 * SOES's hardware layer (esc.h: ESC_read, ESC_write, ESC_init, ESC_reset; esc_eep.h: EEP_read,
 * EEP_write) on the PDI of the project's emulated ESC (libesi/include/esi/esc/pdi.hpp), which
 * the host passes in through esi_soes_attach. Test code only: it is linked with SOES (GPLv2 with
 * a linking exception) and never shipped.
 *
 * The emulated ESC gives every PDI access the side effects of a real one (reading AL control
 * acknowledges the AL control event, the mailbox and buffered SyncManagers switch on their first
 * and last byte), so the HAL forwards accesses one to one and adds nothing. What it adds is what
 * SOES expects of every HAL it ships (the LAN9252 ones): after each access ESCvar.ALevent holds
 * the AL event request register 0x0220, because SOES polls that copy instead of the register.
 * It reads the raw request rather than Pdi::al_event(), which masks with 0x0204: the mask gates
 * the interrupt line (SOES's interrupt mode masks events while ecat_slv_worker serves them), not
 * the events SOES's polling sees, and SOES's own HALs read 0x0220 unmasked too.
 */
#include <string.h>

#include "esc.h"
#include "esc_eep.h"
#include "soes_firmware.h"

static struct esi_soes_pdi pdi;

void esi_soes_attach (const struct esi_soes_pdi *p) { pdi = *p; }

static void refresh_al_event (void)
{
   uint8_t event[4];
   pdi.read (pdi.context, ESCREG_ALEVENT, event, sizeof event);
   ESCvar.ALevent = (uint32_t)event[0] | ((uint32_t)event[1] << 8) | ((uint32_t)event[2] << 16) |
                    ((uint32_t)event[3] << 24);
}

void ESC_read (uint16_t address, void *buf, uint16_t len)
{
   pdi.read (pdi.context, address, buf, len);
   refresh_al_event ();
}

void ESC_write (uint16_t address, void *buf, uint16_t len)
{
   pdi.write (pdi.context, address, buf, len);
   refresh_al_event ();
}

/* The emulator's ESC is up once the host polls the stack (the line runs stacks only on an ESC
 * whose PDI is operational): nothing to open or reset. */
void ESC_init (const esc_cfg_t *config) { (void)config; }

void ESC_reset (void) {}

/* SOES's EEPROM emulation (ESC_EEP, esc_hw_eep_handler) answers the ESC's EEPROM commands from
 * the PDI side on ESCs that delegate them. The emulated ESC loads and serves its SII image
 * itself, so the stack runs without the handler; the hooks still answer from the same image,
 * read-only, for firmware that looks at its own EEPROM. */
int8_t EEP_read (uint32_t addr, uint8_t *data, uint16_t size)
{
   if (pdi.eeprom == NULL || addr > pdi.eeprom_size || size > pdi.eeprom_size - addr) return -1;
   memcpy (data, pdi.eeprom + addr, size);
   return 0;
}

int8_t EEP_write (uint32_t addr, uint8_t *data, uint16_t size)
{
   (void)addr;
   (void)data;
   (void)size;
   return -1;
}
