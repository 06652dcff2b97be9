/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   The checksum file of fix grflow/checksum (both hosts): FILE.cksum next
   to a restart file FILE, one line in the format of the POSIX `cksum`
   utility,
     CRC SIZE NAME
   CRC the POSIX cksum CRC-32 of the file's bytes (polynomial 0x04C11DB7,
   most significant bit first, the length appended, complemented), SIZE
   its length in bytes, NAME its name without the directory.  So
   `cksum FILE` prints the same first two fields, and a file verifies when
   they match.  The checksum file is written to FILE.cksum.tmp and renamed,
   so it is either complete or absent.  No host type here.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_CHECKSUM_H
#define LMP_GRFLOW_CHECKSUM_H

#include <cstdint>
#include <cstdio>
#include <string>

namespace LAMMPS_NS {
namespace GRFLOW {

  // the table of the MSB-first CRC-32 with the polynomial of POSIX cksum
  struct CksumTable {
    uint32_t entry[256];
    CksumTable()
    {
      for (uint32_t i = 0; i < 256; i++) {
        uint32_t c = i << 24;
        for (int k = 0; k < 8; k++) c = (c & 0x80000000u) ? (c << 1) ^ 0x04C11DB7u : (c << 1);
        entry[i] = c;
      }
    }
  };

  // POSIX cksum of a byte stream, fed in pieces
  class Cksum {
   public:
    void add(const unsigned char *bytes, size_t n)
    {
      static const CksumTable table;
      for (size_t k = 0; k < n; k++)
        crc = (crc << 8) ^ table.entry[((crc >> 24) ^ bytes[k]) & 0xFFu];
      size += n;
    }
    uint64_t length() const { return size; }
    // the CRC of the bytes added so far (the length appended, complemented)
    uint32_t value() const
    {
      Cksum tail = *this;
      unsigned char byte[1];
      for (uint64_t n = size; n != 0; n >>= 8) {
        byte[0] = static_cast<unsigned char>(n & 0xFFu);
        tail.add(byte, 1);
      }
      return ~tail.crc;
    }

   private:
    uint32_t crc = 0;
    uint64_t size = 0;
  };

  // FILE's name without its directory
  static inline std::string checksum_base_name(const std::string &file)
  {
    const size_t slash = file.find_last_of('/');
    return slash == std::string::npos ? file : file.substr(slash + 1);
  }

  // the line of FILE.cksum for FILE ("CRC SIZE NAME\n"); message says why
  // not when the file cannot be read (then the result is empty)
  static inline std::string checksum_line(const std::string &file, std::string &message)
  {
    FILE *fp = fopen(file.c_str(), "rb");
    if (!fp) {
      message = "cannot open " + file + " to compute its checksum";
      return "";
    }
    Cksum sum;
    unsigned char buffer[1 << 16];
    size_t n;
    while ((n = fread(buffer, 1, sizeof(buffer), fp)) > 0) sum.add(buffer, n);
    const bool bad = ferror(fp) != 0;
    fclose(fp);
    if (bad) {
      message = "error reading " + file + " to compute its checksum";
      return "";
    }
    return std::to_string(sum.value()) + " " + std::to_string(sum.length()) + " " +
        checksum_base_name(file) + "\n";
  }

  // write FILE.cksum for FILE (through FILE.cksum.tmp and a rename); an
  // empty result on success, else what went wrong
  static inline std::string write_checksum_file(const std::string &file)
  {
    std::string message;
    const std::string line = checksum_line(file, message);
    if (line.empty()) return message;
    const std::string target = file + ".cksum", tmp = target + ".tmp";
    FILE *fp = fopen(tmp.c_str(), "w");
    if (!fp) return "cannot write " + tmp;
    const bool written = fputs(line.c_str(), fp) >= 0;
    if ((fclose(fp) != 0) || !written) return "cannot write " + tmp;
    if (rename(tmp.c_str(), target.c_str()) != 0) return "cannot rename " + tmp + " to " + target;
    return "";
  }

  // the name the restart command gives the file of a step: the first '*'
  // of its pattern replaced by the step
  static inline std::string restart_file_of_step(const std::string &pattern, long long step)
  {
    std::string file = pattern;
    const size_t star = file.find('*');
    if (star != std::string::npos) file.replace(star, 1, std::to_string(step));
    return file;
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
