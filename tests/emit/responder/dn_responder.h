/* A minimal DeviceNet slave (Group 2 only server) built on nothing but the
 * header `edsc header` generates: the proof, under test, that the header is
 * enough to bring a slave on line. Test code, not part of edsc. Portable C99. */
#ifndef DN_RESPONDER_H
#define DN_RESPONDER_H

#include <stdint.h>

typedef struct dn_frame {
  uint16_t id; /* 11-bit CAN identifier */
  uint8_t len;
  uint8_t data[8];
} dn_frame;

typedef struct dn_slave {
  uint8_t mac;
  uint8_t online;     /* the duplicate MAC ID check has been sent */
  uint8_t allocated;  /* allocation choice bits in effect */
  uint8_t master_mac;
  uint8_t watchdog_action[5]; /* per connection instance 1..4 */
  uint16_t expected_packet_rate[5];
  uint16_t production_inhibit[5];
  uint16_t ack_timer;
  uint8_t ack_retry_limit;
  /* A reply longer than one frame, sent fragment by fragment as the master acknowledges. */
  uint8_t reply[48];
  uint8_t reply_len, reply_sent, reply_hdr, fragment_count, fragmenting;
} dn_slave;

void dn_init(dn_slave *s, uint8_t mac);

/* Handles one frame seen on the bus. Returns 1 and fills *out when the slave
 * transmits a frame in reaction, else 0. */
int dn_receive(dn_slave *s, const dn_frame *in, dn_frame *out);

#endif
