package dev.trade.bench;

import io.grpc.CallOptions;
import io.grpc.KnownLength;
import io.grpc.ManagedChannel;
import io.grpc.MethodDescriptor;
import io.grpc.Server;
import io.grpc.ServerServiceDefinition;
import io.grpc.netty.shaded.io.grpc.netty.NettyChannelBuilder;
import io.grpc.netty.shaded.io.grpc.netty.NettyServerBuilder;
import io.grpc.stub.ClientCalls;
import io.grpc.stub.ServerCalls;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.util.concurrent.TimeUnit;

/**
 * gRPC-java unary calls over Netty (HTTP/2, plaintext, loopback), with default executors on both
 * sides, one channel shared by all calling threads and a 30 s deadline per call (as TRADE's calls
 * have one). Messages are plain byte arrays with a hand-written marshaller instead of protobuf
 * classes, so no protoc is needed: the bytes on the wire are what a protobuf {@code bytes}/{@code
 * int32} message would cost within a few bytes, and protobuf's encoding time is left out, which
 * favours gRPC slightly.
 */
final class Grpc {
  private static final MethodDescriptor.Marshaller<byte[]> BYTES = new MethodDescriptor.Marshaller<>() {
    @Override
    public InputStream stream(byte[] value) {
      return new Bytes(value);
    }

    @Override
    public byte[] parse(InputStream in) {
      try {
        return in.readAllBytes();
      } catch (IOException e) {
        throw new UncheckedIOException(e);
      }
    }
  };

  /** Lets gRPC size the message without copying it first. */
  private static final class Bytes extends ByteArrayInputStream implements KnownLength {
    Bytes(byte[] b) {
      super(b);
    }
  }

  private static final MethodDescriptor<byte[], byte[]> SMALL = method("Small");
  private static final MethodDescriptor<byte[], byte[]> CONSUME = method("Consume");
  private static final int MAX_MESSAGE = 8 << 20;

  private static MethodDescriptor<byte[], byte[]> method(String name) {
    return MethodDescriptor.<byte[], byte[]>newBuilder()
        .setType(MethodDescriptor.MethodType.UNARY)
        .setFullMethodName(MethodDescriptor.generateFullMethodName("bench.Bench", name))
        .setRequestMarshaller(BYTES)
        .setResponseMarshaller(BYTES)
        .build();
  }

  private Grpc() {}

  static Rpc.Server serve() throws IOException {
    ServerServiceDefinition service = ServerServiceDefinition.builder("bench.Bench")
        .addMethod(SMALL, ServerCalls.asyncUnaryCall((request, reply) -> {
          reply.onNext(new byte[] {(byte) (Rpc.Service.small(ByteBuffer.wrap(request).getInt()) ? 1 : 0)});
          reply.onCompleted();
        }))
        .addMethod(CONSUME, ServerCalls.asyncUnaryCall((request, reply) -> {
          reply.onNext(ByteBuffer.allocate(4).putInt(Rpc.Service.consume(request)).array());
          reply.onCompleted();
        }))
        .build();
    Server server = NettyServerBuilder.forAddress(new InetSocketAddress("127.0.0.1", 0))
        .addService(service)
        .maxInboundMessageSize(MAX_MESSAGE)
        .build()
        .start();
    return new Rpc.Server() {
      @Override
      public String address() {
        return "127.0.0.1:" + server.getPort();
      }

      @Override
      public void close() throws InterruptedException {
        server.shutdownNow().awaitTermination(5, TimeUnit.SECONDS);
      }
    };
  }

  static Rpc connect(String address) {
    String[] hp = address.split(":");
    ManagedChannel channel = NettyChannelBuilder.forAddress(hp[0], Integer.parseInt(hp[1]))
        .usePlaintext()
        .maxInboundMessageSize(MAX_MESSAGE)
        .build();
    return new Rpc() {
      @Override
      public boolean small(int x) {
        byte[] r = ClientCalls.blockingUnaryCall(channel, SMALL, options(),
            ByteBuffer.allocate(4).putInt(x).array());
        return r[0] != 0;
      }

      @Override
      public int consume(byte[] data) {
        return ByteBuffer.wrap(ClientCalls.blockingUnaryCall(channel, CONSUME, options(), data)).getInt();
      }

      private CallOptions options() {
        return CallOptions.DEFAULT.withDeadlineAfter(30, TimeUnit.SECONDS);
      }

      @Override
      public void close() throws InterruptedException {
        channel.shutdownNow().awaitTermination(5, TimeUnit.SECONDS);
      }
    };
  }
}
