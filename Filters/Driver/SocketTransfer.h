// Blocking whole-buffer transfers on stream sockets, shared by the TetGen worker protocol and the
// process that starts the workers.
#ifndef cgmesh_SocketTransfer_h
#define cgmesh_SocketTransfer_h

#include <cstddef>

namespace cgmesh
{

// Sends all `size` bytes; false if the peer is gone or the send failed. MSG_NOSIGNAL: a dead peer
// must not raise SIGPIPE in the sender.
bool sendAll(int socket, const void* data, std::size_t size);

// Receives exactly `size` bytes; false at end of input, on a timeout or an error.
bool receiveAll(int socket, void* data, std::size_t size);

} // namespace cgmesh

#endif
