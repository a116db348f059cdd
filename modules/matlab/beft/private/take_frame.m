function [s, event] = take_frame(s, wait_ms)
% The next frame from the bridge, up to WAIT_MS: event.kind is 'data' (a
% message on a channel subscribed: event.topic, event.message), 'closed'
% (event.reason), 'advertised' (new server channels) or '' (nothing for
% the expert). Status messages are handled here; the run's history for a
% resuming expert waits in beft.BridgeSocket (history_events).
  event = struct('kind', '', 'topic', '', 'message', [], 'reason', '');
  kind = char(s.socket.next(wait_ms));
  switch kind
    case 'data'
      sid = s.socket.subscription();
      if sid >= 1 && sid <= numel(s.subscribed)
        event.kind = 'data';
        event.topic = s.subscribed{sid};
        [s, event.message] = decoded(s, event.topic, char(s.socket.text()), char(s.socket.hex()));
      end
    case 'closed'
      event.kind = 'closed';
      event.reason = char(s.socket.text());
    case 'text'
      [s, event.kind] = on_server_text(s, beft_json_decode(char(s.socket.text()), char(s.socket.hex())));
  end
end

% A FIRE is re-sent every 5 ms until its DONE is heard: the same text is
% decoded once.
function [s, message] = decoded(s, topic, text, hex)
  if strcmp(topic, 'FIRE') && strcmp(text, s.last_fire.text) && strcmp(hex, s.last_fire.hex)
    message = s.last_fire.message;
    return;
  end
  message = beft_json_decode(text, hex);
  if strcmp(topic, 'FIRE')
    s.last_fire = struct('text', text, 'hex', hex, 'message', message);
  end
end

function [s, kind] = on_server_text(s, message)
  kind = '';
  if ~isstruct(message) || ~isfield(message, 'op')
    return;
  end
  switch message.op
    case 'advertise'
      s = on_advertise(s, message.channels);
      kind = 'advertised';
    case 'status'
      s = on_status(s, message);
  end
end

% The server's channels; the schemas of the channels the expert writes are
% kept to write its messages by (beft_json_encode).
function s = on_advertise(s, channels)
  if isstruct(channels)
    channels = num2cell(channels);
  end
  for i = 1:numel(channels)
    channel = channels{i};
    s.server_topics{end + 1} = channel.topic;
    s.server_ids(end + 1) = channel.id;
    if any(strcmp(s.client_topics, channel.topic)) && isfield(channel, 'schema') && ...
       isvarname(channel.topic) && ~isempty(channel.schema)
      s.schemas.(channel.topic) = jsondecode(channel.schema);
    end
  end
end

function s = on_status(s, status)
  id = '';
  if isfield(status, 'id')
    id = status.id;
  end
  mine = ['beft.expert.' s.name];
  if strcmp(id, mine)
    s.accepted = status.level ~= 2;
    say(s.name, 'bridge: %s', status.message);
  elseif strncmp(id, [mine '.'], numel(mine) + 1)
    say(s.name, 'bridge refused: %s', status.message);
    if isempty(s.accepted) && status.level == 2
      s.accepted = false;
    end
  end
end
