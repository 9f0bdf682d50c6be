package dev.trade.internal.codec;

import dev.trade.internal.registry.ServiceDescriptor;

/**
 * Connects the codec to the container's {@code TRADEServiceInfo} type without the codec knowing it.
 * A service info travels as its {@link ServiceDescriptor} and is bound again on the receiving side,
 * to a handle that calls the service through that container.
 *
 * <p>Implementations must be safe for concurrent use: one codec serves every thread.
 */
public interface InfoBinding {

  /** For codecs that never see service infos: describes nothing, binds to the descriptor itself. */
  InfoBinding NONE =
      new InfoBinding() {
        @Override
        public ServiceDescriptor describe(Object value) {
          return null;
        }

        @Override
        public Object bind(ServiceDescriptor descriptor) {
          return descriptor;
        }
      };

  /** For service tables: descriptors travel as themselves and stay descriptors. */
  InfoBinding DESCRIPTORS =
      new InfoBinding() {
        @Override
        public ServiceDescriptor describe(Object value) {
          return value instanceof ServiceDescriptor ? (ServiceDescriptor) value : null;
        }

        @Override
        public Object bind(ServiceDescriptor descriptor) {
          return descriptor;
        }
      };

  /**
   * Returns the descriptor of {@code value} if it is a {@code TRADEServiceInfo}, or null if it is
   * anything else. Must be cheap: the encoder asks it for every value of a class it does not know.
   */
  ServiceDescriptor describe(Object value);

  /**
   * Returns the {@code TRADEServiceInfo} for a decoded descriptor. An unchecked exception thrown here
   * is reported to the decoder's caller as a {@code TRADESerializationException}.
   */
  Object bind(ServiceDescriptor descriptor);
}
