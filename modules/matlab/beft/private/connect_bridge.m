function socket = connect_bridge(process_name, url, timeout_s)
% A beft.BridgeSocket to the bridge at URL, tried every 0.2 s for up to
% TIMEOUT_S (the bridge may start after this process); [] if it never
% answered.
  started = tic;
  while true
    try
      socket = javaObject('beft.BridgeSocket', url, max(1, min(5, timeout_s)));
      return;
    catch err
      if toc(started) >= timeout_s
        say(process_name, 'cannot connect to the bridge at %s: %s', url, first_line(err.message));
        socket = [];
        return;
      end
      pause(0.2);
    end
  end
end

function line = first_line(text)
  line = strtrim(strtok(text, sprintf('\n')));
end
