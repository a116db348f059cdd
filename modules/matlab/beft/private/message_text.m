function text = message_text(s, topic, message)
% A message for one of the client's channels as JSON, written by the
% schema the server advertised for it (arrays, integers and booleans as
% the type says).
  schema = [];
  if isvarname(topic) && isfield(s.schemas, topic)
    schema = s.schemas.(topic);
  end
  text = beft_json_encode(message, schema);
end
