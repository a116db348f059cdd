function message = message_of_tick(port, tick)
% The newest message of tick k kept by a port, or []: from the newest
% message back, one simulated time at a time (the C++ ChannelHistory).
  message = [];
  k = numel(port.messages);
  while k > 0
    if port.ticks(k) == tick
      message = port.messages{k};
      return;
    end
    k = find(port.utimes <= port.utimes(k) - 1, 1, 'last');
    if isempty(k)
      return;
    end
  end
end
