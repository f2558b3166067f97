/* Prints the identity the generated header gives the firmware. */
#include <stdio.h>

#include "device.h"

int main(void) {
  static const uint8_t name[] = EDS_PRODUCT_NAME_BYTES;
  printf("%u %u %u %u.%u %08lX %s %u\n", (unsigned)EDS_VENDOR_ID, (unsigned)EDS_DEVICE_TYPE,
         (unsigned)EDS_PRODUCT_CODE, (unsigned)EDS_MAJOR_REVISION, (unsigned)EDS_MINOR_REVISION,
         (unsigned long)EDS_SERIAL_NUMBER, EDS_PRODUCT_NAME, (unsigned)name[0]);
  return 0;
}
