// Attack: reach the network (loopback, then anything) and say so in the feedback.
#include <problems/1b/contract.hpp>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdio>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  for (int family : {AF_INET, AF_INET6, AF_NETLINK, AF_PACKET}) {
    const int s = socket(family, family == AF_NETLINK || family == AF_PACKET ? SOCK_RAW : SOCK_STREAM, 0);
    if (s >= 0) {
      std::printf("NETWORK SOCKET OPENED (family %d)\n", family);
      close(s);
    }
  }
  return Vector6d::Zero();
}
}  // namespace opspace::hw2::p1b
