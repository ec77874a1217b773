/*
 * What the SOES firmware of the esi-sim tests exports to its host program (host/soes_host.cpp):
 * the real SOES core, a generated SOES set (objectlist.c, utypes.h, ecat_options.h) and the HAL
 * in soes_hal.c, compiled by the test into one shared object per sample and loaded with dlopen.
 * SOES keeps its state in globals, so one loaded copy is one slave; a host that runs several
 * loads copies of the file under different names.
 *
 * Plain C with fixed-width types only: the host is C++ and never sees SOES's own headers.
 */
#ifndef ESI_SOES_FIRMWARE_H
#define ESI_SOES_FIRMWARE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The emulated ESC's PDI (esi::esc::Pdi) as the host passes it in. */
struct esi_soes_pdi
{
   void *context;
   void (*read) (void *context, uint16_t address, void *buffer, uint16_t length);
   void (*write) (void *context, uint16_t address, const void *buffer, uint16_t length);
   const uint8_t *eeprom; /* the SII image the ESC loaded, for SOES's EEPROM hooks */
   uint32_t eeprom_size;
};

/* Points the HAL at the PDI; called before every esi_soes_* call that reaches the ESC. */
void esi_soes_attach (const struct esi_soes_pdi *pdi);
/* ecat_slv_init(): needs the ESC's PDI operational (DL status bit 0), or it waits forever. */
void esi_soes_init (void);
/* One iteration of SOES's main loop: ecat_slv(). */
void esi_soes_run (void);
/* AL status as SOES last set it (ESCvar.ALstatus). */
uint8_t esi_soes_al_status (void);
/* An object's value (up to 64 bits) in the SOES object dictionary; 0 on success, -1 when the
 * object or sub-index is absent or wider than 64 bits. */
int esi_soes_get (uint16_t index, uint8_t subindex, uint64_t *value, uint16_t *bit_length);
int esi_soes_set (uint16_t index, uint8_t subindex, uint64_t value);

#ifdef __cplusplus
}
#endif

#endif /* ESI_SOES_FIRMWARE_H */
