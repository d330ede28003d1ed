/* SPDX-License-Identifier: MIT */
/* The part of the Arduino API the packaging test's sketches use: setup/loop, millis and a Serial
   that prints through newlib's stdout. Not a board support package: it links, and on a host or
   under an emulator it prints. */
#ifndef TRISTREAM_TEST_ARDUINO_H
#define TRISTREAM_TEST_ARDUINO_H

#include <stddef.h>
#include <stdint.h>

#define HEX 16
#define DEC 10

#ifdef __cplusplus
extern "C" {
#endif
void setup(void);
void loop(void);
unsigned long millis(void);
#ifdef __cplusplus
}

class SerialPort {
 public:
  void begin(unsigned long baud);
  void print(const char* text);
  void print(long value, int base = DEC);
  void print(unsigned long value, int base = DEC);
  void print(unsigned int value, int base = DEC) { print(static_cast<unsigned long>(value), base); }
  void print(int value, int base = DEC) { print(static_cast<long>(value), base); }
  template <typename T>
  void println(T value) { print(value); print("\r\n"); }
  template <typename T>
  void println(T value, int base) { print(value, base); print("\r\n"); }
};
extern SerialPort Serial;
#endif

#endif
